#include "scene/loaders/pbrt/pbrt_materials.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "scene/loaders/pbrt/pbrt_hair.h"
#include "scene/loaders/pbrt/pbrt_spectra.h"
#include "scene/loaders/pbrt/pbrt_subsurface.h"

namespace candela {

namespace {

// pbrt's roughness parameters: an alpha of the microfacet distribution, or with remaproughness (the default) a
// value whose square root is alpha. candela's roughness is sqrt(alpha).
float candelaRoughness(float pbrtRoughness, bool remap) {
  float roughness = std::max(0.0f, pbrtRoughness);
  float alpha = remap ? std::sqrt(roughness) : roughness;
  return std::clamp(std::sqrt(alpha), 0.0f, 1.0f);
}

float candelaRoughness(const PbrtParameters& params, const std::string& prefix, float fallback) {
  float u = params.getFloat(prefix + "uroughness", params.getFloat(prefix + "roughness", fallback));
  float v = params.getFloat(prefix + "vroughness", params.getFloat(prefix + "roughness", fallback));
  return candelaRoughness(0.5f * (u + v), params.getBool("remaproughness", true));
}

float scalarIor(const PbrtParameters& params, const std::string& name, float fallback) {
  if (std::optional<PbrtColor> c = params.getColor(name)) return c->rgb.y;  // near 550 nm
  return fallback;
}

// A reflectance or transmittance, pbrt's colour times `scale`, clamped to [0, 1] as pbrt-v4 clamps them.
Vec3 unitColour(Vec3 c, const PbrtParameters& params, const std::string& what) {
  if (!isFinite(c)) params.fail(what + " is not finite");
  return {std::clamp(c.x, 0.0f, 1.0f), std::clamp(c.y, 0.0f, 1.0f), std::clamp(c.z, 0.0f, 1.0f)};
}

}  // namespace

uint32_t PbrtMaterials::add(const Material& m, const std::string& name, const PbrtTexture* baseTexture) {
  uint32_t id = uint32_t(context_.scene.materials.size());
  context_.scene.materials.push_back(m);
  context_.scene.materialNames.push_back(name);
  if (baseTexture && baseTexture->image != kNoTexture) uvMappings_[id] = {baseTexture->uvScale, baseTexture->uvOffset};
  return id;
}

const Medium* PbrtMaterials::interior(uint32_t materialId) const {
  auto found = interiors_.find(materialId);
  return found == interiors_.end() ? nullptr : &found->second;
}

void PbrtMaterials::noteVariant(uint32_t base, uint32_t variant) {
  if (const Medium* medium = interior(base)) interiors_[variant] = *medium;
}

std::pair<Vec2, Vec2> PbrtMaterials::uvMapping(uint32_t materialId) const {
  auto found = uvMappings_.find(materialId);
  return found == uvMappings_.end() ? std::pair{Vec2{1, 1}, Vec2{0, 0}} : found->second;
}

PbrtMaterial PbrtMaterials::fallback() {
  if (!fallback_) fallback_ = add(Material{.baseColor = {0.5f, 0.5f, 0.5f}}, "pbrt default diffuse");
  return PbrtMaterial{*fallback_};
}

Material PbrtMaterials::translate(const std::string& type, const PbrtParameters& params,
                                  const PbrtTexture*& baseTexture) {
  Material m;
  auto colour = [&](const std::string& name, Vec3 fallbackValue) {
    baseTexture_ = textures_.value(params, name, fallbackValue);
    m.baseColor = baseTexture_.factor;
    m.baseColorTexture = baseTexture_.image;
    baseTexture = &baseTexture_;
  };
  auto conductorF0 = [&](const std::string& prefix) {
    if (params.find(prefix + "reflectance")) {
      PbrtTexture r = textures_.value(params, prefix + "reflectance", {1, 1, 1});
      m.baseColorTexture = r.image;
      baseTexture_ = r;
      baseTexture = &baseTexture_;
      return r.factor;
    }
    Vec3 eta = namedSpectrumRgb("metal-Cu-eta").value(), k = namedSpectrumRgb("metal-Cu-k").value();
    if (params.getTexture(prefix + "eta") || params.getTexture(prefix + "k"))
      context_.warn("textured conductor", "textured conductor 'eta'/'k' are not supported: copper used");
    else {
      if (auto e = params.getColor(prefix + "eta")) eta = e->rgb;
      if (auto kk = params.getColor(prefix + "k")) k = kk->rgb;
    }
    return conductorReflectance(eta, k);
  };
  // The roughness of the main lobe: numbers, or a texture turned into an image of candela's roughness per texel
  // (the material's roughness is then 1, which the texture multiplies).
  auto roughness = [&](const std::string& prefix, float fallbackValue) {
    std::string name = prefix + "roughness";
    if (!params.getTexture(name)) name = prefix + "uroughness";
    if (!params.getTexture(name)) return candelaRoughness(params, prefix, fallbackValue);
    if (params.find(prefix + "vroughness"))
      context_.warn("anisotropic roughness texture", "a textured 'uroughness' stands for 'vroughness' too");
    bool remap = params.getBool("remaproughness", true);
    PbrtTexture t = textures_.value(params, name, {fallbackValue, fallbackValue, fallbackValue});
    if (t.image == kNoTexture) return candelaRoughness(t.factor.x, remap);
    float scale = t.factor.x;
    m.roughnessTexture = textures_.mappedImage(
        t.image, "roughness " + std::to_string(scale) + (remap ? " remapped" : ""),
        [=](float v) { return candelaRoughness(scale * v, remap); }, params.file + ":" + std::to_string(params.line),
        "the roughness of texture '" + *params.getTexture(name) + "'");
    return 1.0f;
  };
  // pbrt's DielectricBxDF of index `eta`: smooth glass, or the Disney model's rough transmission.
  auto dielectric = [&](float eta) {
    float r = roughness("", 0.0f);
    m.baseColor = {1, 1, 1};
    m.ior = eta;
    if (r == 0.0f) {
      m.type = MaterialType::Glass;
    } else {
      m.type = MaterialType::Disney;
      m.specTrans = 1.0f;
      m.metallic = 0.0f;
      m.roughness = r;
    }
  };
  if (params.getTexture("interface.roughness"))
    context_.warn("textured coat roughness", "a textured 'interface.roughness' is not supported: 0 is used");

  if (type == "diffuse") {
    colour("reflectance", {0.5f, 0.5f, 0.5f});
  } else if (type == "coateddiffuse") {
    colour("reflectance", {0.5f, 0.5f, 0.5f});
    m.type = MaterialType::Pbr;
    m.metallic = 0.0f;
    m.roughness = roughness("", 0.0f);
    float eta = scalarIor(params, "eta", 1.5f);
    m.specular = std::clamp(sqr((eta - 1.0f) / (eta + 1.0f)) / 0.08f, 0.0f, 1.0f);
  } else if (type == "conductor") {
    Vec3 f0 = conductorF0("");
    float r = roughness("", 0.0f);
    if (r == 0.0f && m.baseColorTexture == kNoTexture) {
      m.type = MaterialType::Mirror;
      m.specularColor = f0;
    } else {
      m.type = MaterialType::Pbr;
      m.metallic = 1.0f;
      m.baseColor = f0;
      m.roughness = r;
    }
  } else if (type == "coatedconductor") {
    m.type = MaterialType::Disney;
    m.baseColor = conductorF0("conductor.");
    m.metallic = 1.0f;
    m.roughness = roughness("conductor.", 0.0f);
    m.clearcoat = 1.0f;
    m.clearcoatGloss = 1.0f - candelaRoughness(params, "interface.", 0.0f);
  } else if (type == "dielectric") {
    float eta = scalarIor(params, "eta", 1.5f);
    dielectric(eta > 0.0f ? eta : 1.5f);
  } else if (type == "subsurface") {
    // A dielectric boundary around the medium of a random walk (kernel/media/subsurface_walk.h).
    const float eta = params.getFloat("eta", 1.33f);
    if (!(eta > 0.0f) || !std::isfinite(eta)) params.fail("subsurface: 'eta' must be finite and positive");
    dielectric(eta);
    pendingInterior_ = pbrtSubsurfaceInterior(params, textures_, context_);
  } else if (type == "thindielectric") {
    // A thin sheet reflects 2R/(1+R) of the light at normal incidence and lets the rest through undeviated:
    // a white mirror that rays pass with the transmitted probability.
    float eta = scalarIor(params, "eta", 1.5f);
    float r = sqr((eta - 1.0f) / (eta + 1.0f));
    m.type = MaterialType::Mirror;
    m.specularColor = {1, 1, 1};
    m.alphaMode = AlphaMode::Blend;
    m.opacity = 2.0f * r / (1.0f + r);
    context_.warn("material thindielectric",
                  "'thindielectric' is rendered with its reflectance at normal incidence "
                  "at every angle");
  } else if (type == "diffusetransmission") {
    // pbrt-v4's DiffuseTransmissionMaterial: both colours (0.25 by default) times `scale`, clamped to [0, 1].
    const float scale = params.getFloat("scale", 1.0f);
    if (!(scale >= 0.0f) || !std::isfinite(scale))
      params.fail("diffusetransmission: 'scale' must be finite and not negative");
    m.type = MaterialType::DiffuseTransmission;
    colour("reflectance", {0.25f, 0.25f, 0.25f});
    // A texture's texels multiply the factor, which pbrt's clamp of the product cannot bound beforehand.
    m.baseColor = m.baseColorTexture == kNoTexture
                      ? unitColour(m.baseColor * scale, params, "diffusetransmission: 'reflectance'")
                      : m.baseColor * scale;
    if (!isFinite(m.baseColor)) params.fail("diffusetransmission: 'reflectance' is not finite");
    const PbrtTexture transmittance = textures_.value(params, "transmittance", {0.25f, 0.25f, 0.25f});
    if (transmittance.image != kNoTexture)
      context_.warn("textured transmittance",
                    "a textured diffusetransmission 'transmittance' is rendered with its mean colour");
    m.transmittance =
        unitColour(textures_.meanColour(transmittance) * scale, params, "diffusetransmission: 'transmittance'");
  } else if (type == "hair") {
    m = pbrtHairMaterial(params, textures_, context_);
  } else if (type == "interface" || type.empty() || type == "none") {
    // The boundary of participating media (MediumInterface), which rays cross unchanged.
    m.interfaceOnly = 1;
    m.alphaMode = AlphaMode::Mask;
    m.opacity = 0.0f;
  } else if (type == "matte" || type == "plastic" || type == "uber" || type == "substrate" || type == "translucent") {
    // pbrt-v3's materials, by their diffuse colour; plastic with its specular layer as coateddiffuse does.
    colour("Kd", {0.5f, 0.5f, 0.5f});
    if (type == "plastic") {
      m.type = MaterialType::Pbr;
      m.roughness = candelaRoughness(params, "", 0.1f);
    } else if (type != "matte") {
      context_.warn("material " + type, "pbrt-v3's '" + type + "' material is rendered as diffuse 'Kd'");
    }
  } else if (type == "mirror") {
    m.type = MaterialType::Mirror;
    m.specularColor = params.getColor("Kr").value_or(PbrtColor{{0.9f, 0.9f, 0.9f}}).rgb;
  } else if (type == "glass") {
    m.type = MaterialType::Glass;
    m.baseColor = {1, 1, 1};
    m.ior = scalarIor(params, "index", scalarIor(params, "eta", 1.5f));
  } else if (type == "metal") {
    m.type = MaterialType::Pbr;
    m.metallic = 1.0f;
    m.baseColor = conductorF0("");
    m.roughness = candelaRoughness(params, "", 0.01f);
  } else {
    colour("reflectance", {0.5f, 0.5f, 0.5f});
    params.markAllUsed();
    context_.warn("material " + type, "'" + type + "' materials are not supported: rendered as diffuse");
  }
  if (params.find("displacement")) context_.warn("displacement", "'displacement' is not applied");
  std::string normalMap = params.getString("normalmap", "");
  if (!normalMap.empty()) m.normalTexture = textures_.loadImage(normalMap, false, params.file, params.line);
  return m;
}

// pbrt-v4's MixMaterial: a shading point takes the second material with probability `amount` (a number or a
// float texture), chosen per point by the kernel (kernel/textured_material.h).
PbrtMaterial PbrtMaterials::makeMix(const PbrtParameters& params) {
  const PbrtParameter* names = params.find("materials");
  if (!names || names->strings.size() != 2) params.fail("mix material needs 'materials' naming two materials");
  Material m;
  m.type = MaterialType::Mix;
  uint32_t depth = 1;
  for (size_t i = 0; i < 2; ++i) {
    uint32_t id = named(names->strings[i], params.file, params.line).id;
    const Material& mixed = context_.scene.materials[id];
    if (mixed.alphaMode != AlphaMode::Opaque)
      context_.warn("mix of see-through material",
                    "'" + names->strings[i] +
                        "' lets light through ('interface', 'thindielectric'), which a mix "
                        "does not choose per point: in the mix it is opaque ('interface' a grey diffuse, "
                        "'thindielectric' a mirror)");
    if (interior(id))
      context_.warn("mix of subsurface material", "'" + names->strings[i] +
                                                      "' is a subsurface material, which a mix renders as its "
                                                      "dielectric boundary without the medium inside");
    auto found = mixDepths_.find(id);
    if (found != mixDepths_.end()) depth = std::max(depth, found->second + 1);
    m.mixedMaterials[i] = id;
  }
  if (depth > kMaxMixDepth) params.fail("mix materials nest more than " + std::to_string(kMaxMixDepth) + " deep");
  PbrtTexture amount = textures_.value(params, "amount", {0.5f, 0.5f, 0.5f});
  m.mixAmountTexture = amount.image;
  // With an image the factor scales texels, which may lie below 1; alone it is the probability.
  m.mixAmount = amount.image != kNoTexture ? std::max(0.0f, amount.factor.x) : std::clamp(amount.factor.x, 0.0f, 1.0f);
  if (!std::isfinite(m.mixAmount)) params.fail("mix material's 'amount' is not a finite number");
  uint32_t id = add(m, pendingName_.empty() ? "pbrt mix" : pendingName_);
  mixDepths_[id] = depth;
  // A mesh's texture coordinates take one mapping (uvMapping): a mixed material's, else the amount texture's.
  for (uint32_t mixed : m.mixedMaterials)
    if (auto found = uvMappings_.find(mixed); found != uvMappings_.end() && !uvMappings_.count(id))
      uvMappings_[id] = found->second;
  if (!uvMappings_.count(id) && amount.image != kNoTexture) uvMappings_[id] = {amount.uvScale, amount.uvOffset};
  return PbrtMaterial{id};
}

PbrtMaterial PbrtMaterials::make(const std::string& type, const PbrtParameters& params) {
  if (type == "mix") return makeMix(params);
  const PbrtTexture* baseTexture = nullptr;
  Material m = translate(type, params, baseTexture);
  std::string name = pendingName_.empty() ? "pbrt " + type : pendingName_;
  const uint32_t id = add(m, name, baseTexture);
  if (pendingInterior_) interiors_[id] = *pendingInterior_;
  pendingInterior_.reset();
  return PbrtMaterial{id};
}

void PbrtMaterials::defineNamed(const std::string& name, const PbrtParameters& params) {
  std::string type = params.getString("type", "");
  if (!params.find("type")) params.fail("named material '" + name + "' without 'type'");
  pendingName_ = name;
  named_[name] = make(type, params);
  pendingName_.clear();
}

PbrtMaterial PbrtMaterials::named(const std::string& name, const std::string& file, size_t line) {
  auto found = named_.find(name);
  if (found != named_.end()) return found->second;
  context_.warn("unknown material " + name, file + ":" + std::to_string(line) + ": material '" + name +
                                                "' is not defined: the default diffuse is used");
  return fallback();
}

}  // namespace candela
