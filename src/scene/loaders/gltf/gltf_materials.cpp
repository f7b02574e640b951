#include "scene/loaders/gltf/gltf_materials.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "scene/loaders/gltf/gltf_specular_glossiness.h"

namespace candela {

bool UvTransform::operator==(const UvTransform& o) const { return std::equal(m, m + 6, o.m); }

namespace {

const tinygltf::Value* extension(const tinygltf::ExtensionMap& map, const char* name) {
  auto it = map.find(name);
  return it == map.end() ? nullptr : &it->second;
}

double number(const tinygltf::Value& object, const char* key, double fallback) {
  if (!object.IsObject() || !object.Has(key)) return fallback;
  const tinygltf::Value& v = object.Get(key);
  return v.IsNumber() ? v.GetNumberAsDouble() : fallback;
}

std::vector<double> numbers(const tinygltf::Value& object, const char* key, std::vector<double> fallback) {
  if (!object.IsObject() || !object.Has(key)) return fallback;
  const tinygltf::Value& v = object.Get(key);
  if (!v.IsArray() || v.ArrayLen() != fallback.size()) return fallback;
  for (size_t i = 0; i < fallback.size(); ++i)
    if (v.Get(int(i)).IsNumber()) fallback[i] = v.Get(int(i)).GetNumberAsDouble();
  return fallback;
}

bool hasTexture(const tinygltf::Value& object, const char* key) {
  return object.IsObject() && object.Has(key) && object.Get(key).IsObject();
}

float finiteOr(double x, float fallback) { return std::isfinite(x) ? float(x) : fallback; }

UvTransform transformOf(const tinygltf::Value& t) {
  std::vector<double> offset = numbers(t, "offset", {0, 0}), scale = numbers(t, "scale", {1, 1});
  double rotation = number(t, "rotation", 0);
  float c = float(std::cos(rotation)), s = float(std::sin(rotation));
  float sx = finiteOr(scale[0], 1), sy = finiteOr(scale[1], 1);
  // translation * rotation * scale, as the extension defines it.
  UvTransform u;
  u.m[0] = c * sx;
  u.m[1] = s * sy;
  u.m[2] = finiteOr(offset[0], 0);
  u.m[3] = -s * sx;
  u.m[4] = c * sy;
  u.m[5] = finiteOr(offset[1], 0);
  return u;
}

// KHR_materials_volume: light keeps attenuationColor after attenuationDistance inside the material, so the
// absorption coefficient is -ln(colour) / distance per channel. A thickness of 0 (the default) makes the surface
// thin-walled, without a volume. The thickness itself, and its texture, are for renderers that cannot trace the
// volume's far side; a path tracer measures the distance each ray travels inside. The coefficient has effect
// only where light enters the material: with KHR_materials_transmission.
Vec3 absorptionOf(const tinygltf::Value& e) {
  const float thickness = finiteOr(number(e, "thicknessFactor", 0), 0);
  const double distance = number(e, "attenuationDistance", std::numeric_limits<double>::infinity());
  if (!(thickness > 0.0f) || !(distance > 0.0) || !std::isfinite(distance)) return {0, 0, 0};
  const std::vector<double> c = numbers(e, "attenuationColor", {1, 1, 1});
  // A colour of 0 would absorb infinitely (and make 0 * infinity at a zero distance): 1e-6 is black enough.
  auto channel = [&](double colour) {
    const double coefficient = -std::log(std::clamp(std::isfinite(colour) ? colour : 1.0, 1e-6, 1.0)) / distance;
    return float(std::min(coefficient, double(std::numeric_limits<float>::max())));
  };
  return {channel(c[0]), channel(c[1]), channel(c[2])};
}

class TextureRefs {
 public:
  TextureRefs(const std::string& file, const std::string& where, const GltfTextureResolver& resolve,
              LoadWarnings& warnings)
      : file_(file), where_(where), resolve_(resolve), warnings_(warnings) {}

  int32_t use(int index, int texCoord, const tinygltf::ExtensionMap& extensions, bool srgb) {
    if (index < 0) return kNoTexture;
    const tinygltf::Value* t = extension(extensions, "KHR_texture_transform");
    transforms_.push_back(t ? transformOf(*t) : UvTransform{});
    // The transform's texCoord, when it has one, replaces the texture's (KHR_texture_transform).
    // (Clamped before the conversion: a hostile number must not overflow int.)
    double set = t ? number(*t, "texCoord", texCoord) : texCoord;
    texCoords_.push_back(int(std::clamp(set, 0.0, 255.0)));
    return resolve_(index, srgb);
  }

  std::optional<UvTransform> commonTransform() {
    if (transforms_.empty()) return std::nullopt;
    for (const UvTransform& t : transforms_)
      if (!(t == transforms_[0])) {
        warn("textures have different KHR_texture_transform values, which are ignored");
        return std::nullopt;
      }
    if (transforms_[0] == UvTransform{}) return std::nullopt;
    return transforms_[0];
  }

  int commonTexCoord() {
    if (texCoords_.empty()) return 0;
    for (int t : texCoords_)
      if (t != texCoords_[0]) {
        warn("textures read different TEXCOORD sets; all of them read TEXCOORD_0");
        return 0;
      }
    return texCoords_[0];
  }

  void warn(const std::string& what) { warnings_.add(file_, where_ + ": " + what); }

 private:
  const std::string& file_;
  std::string where_;
  const GltfTextureResolver& resolve_;
  LoadWarnings& warnings_;
  std::vector<UvTransform> transforms_;
  std::vector<int> texCoords_;
};

// The texture an extension's textureInfo `key` names (with its texCoord and KHR_texture_transform), or
// kNoTexture where it names none.
int32_t extensionTexture(const tinygltf::Value& e, const char* key, bool srgb, TextureRefs& refs) {
  if (!hasTexture(e, key)) return kNoTexture;
  const tinygltf::Value& info = e.Get(key);
  if (!info.Has("index") || !info.Get("index").IsInt()) return kNoTexture;
  tinygltf::ExtensionMap extensions;
  if (info.Has("extensions") && info.Get("extensions").IsObject())
    for (const std::string& name : info.Get("extensions").Keys()) extensions[name] = info.Get("extensions").Get(name);
  return refs.use(info.Get("index").GetNumberAsInt(), int(std::clamp(number(info, "texCoord", 0), 0.0, 255.0)),
                  extensions, srgb);
}

// KHR_materials_iridescence on `m`: a thin film over the specular lobe of either model (kernel/bsdf/thin_film.h).
void readIridescence(const tinygltf::Value& e, Material& m, TextureRefs& refs) {
  m.iridescence = std::clamp(finiteOr(number(e, "iridescenceFactor", 0), 0), 0.0f, 1.0f);
  m.iridescenceIor = std::max(finiteOr(number(e, "iridescenceIor", 1.3), 1.3f), 1.0f);
  // Thicknesses beyond 1e5 nm interfere at no visible wavelength: the film then reflects as its incoherent sum.
  auto thickness = [&](const char* key, float fallback) {
    return std::clamp(finiteOr(number(e, key, fallback), fallback), 0.0f, 1e5f);
  };
  m.iridescenceThicknessMinimum = thickness("iridescenceThicknessMinimum", 100.0f);
  m.iridescenceThickness = thickness("iridescenceThicknessMaximum", 400.0f);
  m.iridescenceTexture = extensionTexture(e, "iridescenceTexture", false, refs);
  m.iridescenceThicknessTexture = extensionTexture(e, "iridescenceThicknessTexture", false, refs);
}

// KHR_materials_pbrSpecularGlossiness on `m`, which holds the core model's reading of the material.
void convertSpecularGlossiness(const tinygltf::Value& e, Material& m, TextureRefs& refs,
                               const GltfTextureMean& textureMean) {
  auto textureIndex = [&](const char* key) {
    if (!hasTexture(e, key) || !e.Get(key).Has("index") || !e.Get(key).Get("index").IsInt()) return -1;
    return e.Get(key).Get("index").GetNumberAsInt();
  };
  auto texCoordOf = [&](const char* key) {
    return hasTexture(e, key) ? int(std::clamp(number(e.Get(key), "texCoord", 0), 0.0, 255.0)) : 0;
  };
  const std::vector<double> d = numbers(e, "diffuseFactor", {1, 1, 1, 1});
  const std::vector<double> s = numbers(e, "specularFactor", {1, 1, 1});
  const Vec3 diffuseFactor{std::max(finiteOr(d[0], 1), 0.0f), std::max(finiteOr(d[1], 1), 0.0f),
                           std::max(finiteOr(d[2], 1), 0.0f)};
  Vec3 specular{std::max(finiteOr(s[0], 1), 0.0f), std::max(finiteOr(s[1], 1), 0.0f),
                std::max(finiteOr(s[2], 1), 0.0f)};
  float glossiness = std::clamp(finiteOr(number(e, "glossinessFactor", 1), 1), 0.0f, 1.0f);
  m.opacity = std::clamp(finiteOr(d[3], 1), 0.0f, 1.0f);

  const int diffuseTexture = textureIndex("diffuseTexture");
  Vec3 diffuse = diffuseFactor;
  Vec3 diffuseMean{1, 1, 1};
  if (diffuseTexture >= 0) {
    if (std::optional<Vec4> mean = textureMean(diffuseTexture, true)) diffuseMean = {mean->x, mean->y, mean->z};
    diffuse = diffuse * diffuseMean;
  }
  if (const int specularTexture = textureIndex("specularGlossinessTexture"); specularTexture >= 0) {
    if (std::optional<Vec4> mean = textureMean(specularTexture, true)) {
      specular = specular * Vec3{mean->x, mean->y, mean->z};
      glossiness *= mean->w;
      refs.warn(
          "KHR_materials_pbrSpecularGlossiness.specularGlossinessTexture is reduced to its mean specular colour and "
          "glossiness: the metallic-roughness model has no texture for them");
    } else {
      refs.warn("KHR_materials_pbrSpecularGlossiness.specularGlossinessTexture cannot be read and is ignored");
    }
  }
  const MetallicRoughness converted = metallicRoughnessFromSpecularGlossiness(diffuse, specular, glossiness);
  m.metallic = converted.metallic;
  m.roughness = converted.roughness;
  m.metallicRoughnessTexture = kNoTexture;
  // The diffuse texture's variation carries over: the base colour factor takes its mean to the converted colour.
  auto ratio = [](float colour, float mean) { return mean > 1e-4f ? colour / mean : colour; };
  m.baseColor = diffuseTexture >= 0
                    ? Vec3{ratio(converted.baseColor.x, diffuseMean.x), ratio(converted.baseColor.y, diffuseMean.y),
                           ratio(converted.baseColor.z, diffuseMean.z)}
                    : converted.baseColor;
  tinygltf::ExtensionMap diffuseExtensions;  // its KHR_texture_transform
  if (diffuseTexture >= 0 && e.Get("diffuseTexture").Has("extensions")) {
    const tinygltf::Value& extensions = e.Get("diffuseTexture").Get("extensions");
    if (extensions.IsObject())
      for (const std::string& key : extensions.Keys()) diffuseExtensions[key] = extensions.Get(key);
  }
  m.baseColorTexture = diffuseTexture >= 0
                           ? refs.use(diffuseTexture, texCoordOf("diffuseTexture"), diffuseExtensions, true)
                           : kNoTexture;
}

// The extensions whose parameters only the Disney model has.
constexpr const char* kDisneyExtensions[] = {"KHR_materials_transmission", "KHR_materials_ior",
                                             "KHR_materials_clearcoat",    "KHR_materials_sheen",
                                             "KHR_materials_specular",     "KHR_materials_anisotropy"};

// The model glTF material `g` is rendered with: the core metallic-roughness model, Disney where an extension needs
// it, a diffuse surface that emits the base colour for KHR_materials_unlit.
MaterialType gltfMaterialType(const tinygltf::Material& g) {
  if (extension(g.extensions, "KHR_materials_unlit")) return MaterialType::Diffuse;
  for (const char* name : kDisneyExtensions)
    if (extension(g.extensions, name)) return MaterialType::Disney;
  return MaterialType::Pbr;
}

}  // namespace

GltfMaterial materialFromGltf(const tinygltf::Model& model, int index, const std::string& file,
                              const GltfTextureResolver& texture, const GltfTextureMean& textureMean,
                              LoadWarnings& warnings) {
  const tinygltf::Material& g = model.materials[size_t(index)];
  TextureRefs refs(file, "materials[" + std::to_string(index) + "]", texture, warnings);
  GltfMaterial out;
  Material& m = out.material;
  const auto& pbr = g.pbrMetallicRoughness;
  m.type = gltfMaterialType(g);
  if (pbr.baseColorFactor.size() == 4) {
    m.baseColor = {finiteOr(pbr.baseColorFactor[0], 1), finiteOr(pbr.baseColorFactor[1], 1),
                   finiteOr(pbr.baseColorFactor[2], 1)};
    m.opacity = std::clamp(finiteOr(pbr.baseColorFactor[3], 1), 0.0f, 1.0f);
  } else {
    m.baseColor = {1, 1, 1};
  }
  m.metallic = std::clamp(finiteOr(pbr.metallicFactor, 1), 0.0f, 1.0f);
  m.roughness = std::clamp(finiteOr(pbr.roughnessFactor, 1), 0.0f, 1.0f);
  if (const tinygltf::Value* e = extension(g.extensions, "KHR_materials_pbrSpecularGlossiness")) {
    convertSpecularGlossiness(*e, m, refs, textureMean);
  } else {
    m.baseColorTexture =
        refs.use(pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord, pbr.baseColorTexture.extensions, true);
    m.metallicRoughnessTexture = refs.use(pbr.metallicRoughnessTexture.index, pbr.metallicRoughnessTexture.texCoord,
                                          pbr.metallicRoughnessTexture.extensions, false);
  }
  m.normalTexture = refs.use(g.normalTexture.index, g.normalTexture.texCoord, g.normalTexture.extensions, false);
  if (g.normalTexture.index >= 0 && g.normalTexture.scale != 1.0)
    refs.warn("normalTexture.scale " + std::to_string(g.normalTexture.scale) + " is ignored");
  m.emissionTexture = refs.use(g.emissiveTexture.index, g.emissiveTexture.texCoord, g.emissiveTexture.extensions, true);

  float strength = 1.0f;
  if (const tinygltf::Value* e = extension(g.extensions, "KHR_materials_emissive_strength"))
    strength = std::max(finiteOr(number(*e, "emissiveStrength", 1), 1), 0.0f);
  if (g.emissiveFactor.size() == 3)
    m.emission =
        Vec3{std::max(finiteOr(g.emissiveFactor[0], 0), 0.0f), std::max(finiteOr(g.emissiveFactor[1], 0), 0.0f),
             std::max(finiteOr(g.emissiveFactor[2], 0), 0.0f)} *
        strength;

  m.alphaMode = g.alphaMode == "MASK" ? AlphaMode::Mask : g.alphaMode == "BLEND" ? AlphaMode::Blend : AlphaMode::Opaque;
  m.alphaCutoff = finiteOr(g.alphaCutoff, 0.5f);
  m.doubleSided = g.doubleSided ? 1u : 0u;

  // One of kDisneyExtensions, with a warning for each of its textures, which have no slot.
  auto disneyOnly = [&](const char* name, std::initializer_list<const char*> textures) -> const tinygltf::Value* {
    const tinygltf::Value* e = extension(g.extensions, name);
    if (!e) return nullptr;
    for (const char* t : textures)
      if (hasTexture(*e, t))
        refs.warn(std::string(name) + "." + t + " is ignored: the material model has no such texture");
    return e;
  };
  if (const tinygltf::Value* e = disneyOnly("KHR_materials_transmission", {"transmissionTexture"}))
    m.specTrans = std::clamp(finiteOr(number(*e, "transmissionFactor", 0), 0), 0.0f, 1.0f);
  if (const tinygltf::Value* e = disneyOnly("KHR_materials_ior", {}))
    m.ior = std::max(finiteOr(number(*e, "ior", 1.5), 1.5f), 1.0f);
  if (const tinygltf::Value* e = extension(g.extensions, "KHR_materials_volume")) m.absorption = absorptionOf(*e);
  if (const tinygltf::Value* e = disneyOnly("KHR_materials_clearcoat", {"clearcoatTexture", "clearcoatRoughnessTexture",
                                                                        "clearcoatNormalTexture"})) {
    m.clearcoat = std::clamp(finiteOr(number(*e, "clearcoatFactor", 0), 0), 0.0f, 1.0f);
    m.clearcoatGloss = 1.0f - std::clamp(finiteOr(number(*e, "clearcoatRoughnessFactor", 0), 0), 0.0f, 1.0f);
  }
  if (const tinygltf::Value* e = disneyOnly("KHR_materials_sheen", {"sheenColorTexture", "sheenRoughnessTexture"})) {
    // Disney's sheen is a weight with a tint towards the base colour; glTF gives a colour. The weight is the
    // colour's brightest channel; a grey sheen is untinted.
    std::vector<double> c = numbers(*e, "sheenColorFactor", {0, 0, 0});
    Vec3 colour{std::max(finiteOr(c[0], 0), 0.0f), std::max(finiteOr(c[1], 0), 0.0f),
                std::max(finiteOr(c[2], 0), 0.0f)};
    m.sheen = maxComponent(colour);
    m.sheenTint = m.sheen > 0.0f && (colour.x != colour.y || colour.y != colour.z) ? 1.0f : 0.0f;
  }
  if (const tinygltf::Value* e = disneyOnly("KHR_materials_specular", {"specularTexture", "specularColorTexture"})) {
    // Disney's specular 0.5 is glTF's default F0 of 0.04 (ior 1.5) at specularFactor 1.
    m.specular = 0.5f * std::clamp(finiteOr(number(*e, "specularFactor", 1), 1), 0.0f, 1.0f);
    std::vector<double> c = numbers(*e, "specularColorFactor", {1, 1, 1});
    m.specularTint = (c[0] != c[1] || c[1] != c[2]) ? 1.0f : 0.0f;
  }
  if (const tinygltf::Value* e = disneyOnly("KHR_materials_anisotropy", {"anisotropyTexture"})) {
    // glTF stretches the GGX lobe along the tangent to alpha_t = mix(alpha, 1, strength^2), keeping alpha = r^2
    // across it; the Disney lobe has alpha_x = r'^2 / aspect and alpha_y = r'^2 aspect with aspect =
    // sqrt(1 - 0.9 anisotropic). Both alphas match for alpha_t / alpha up to 10, Disney's widest stretch; beyond,
    // alpha_t matches and the lobe is wider across.
    const float stretch = std::clamp(finiteOr(number(*e, "anisotropyStrength", 0), 0), 0.0f, 1.0f);
    const float alpha = m.roughness * m.roughness;
    const float alphaT = alpha + (1.0f - alpha) * stretch * stretch;
    if (alphaT > alpha) {
      const float ratio = alphaT / std::max(alpha, 1e-8f);
      m.anisotropic = std::clamp((1.0f - 1.0f / ratio) / 0.9f, 0.0f, 1.0f);
      m.roughness = std::sqrt(alphaT * std::sqrt(1.0f - 0.9f * m.anisotropic));
    }
    if (finiteOr(number(*e, "anisotropyRotation", 0), 0) != 0.0f)
      refs.warn("KHR_materials_anisotropy.anisotropyRotation is ignored: the lobe is stretched along the tangent");
  }
  if (const tinygltf::Value* e = extension(g.extensions, "KHR_materials_iridescence")) readIridescence(*e, m, refs);
  if (extension(g.extensions, "KHR_materials_unlit")) {
    // Unlit: the base colour is what the camera sees, whatever the lighting. Rendered as a black surface that
    // emits its base colour (texture included), so it also lights its surroundings a little.
    m.emission = m.baseColor;
    m.emissionTexture = m.baseColorTexture;
    m.baseColor = {0, 0, 0};
    m.metallicRoughnessTexture = m.normalTexture = kNoTexture;
    m.iridescence = 0.0f;
    m.iridescenceTexture = m.iridescenceThicknessTexture = kNoTexture;
  }
  out.uvTransform = refs.commonTransform();
  out.texCoord = refs.commonTexCoord();
  return out;
}

}  // namespace candela
