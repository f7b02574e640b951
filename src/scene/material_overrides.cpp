#include "scene/material_overrides.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "kernel/bsdf/material_models.h"
#include "kernel/bsdf/material_type_names.h"

namespace candela {

namespace {

constexpr std::array<OverrideParameter, 9> kParameters = {{
    {"specular", &MaterialOverrides::specular, &Material::specular, 0.0f, 1.0f},
    {"roughness", &MaterialOverrides::roughness, &Material::roughness, 0.0f, 1.0f},
    {"metallic", &MaterialOverrides::metallic, &Material::metallic, 0.0f, 1.0f},
    {"subsurface", &MaterialOverrides::subsurface, &Material::subsurface, 0.0f, 1.0f},
    {"specularTint", &MaterialOverrides::specularTint, &Material::specularTint, 0.0f, 1.0f},
    {"sheen", &MaterialOverrides::sheen, &Material::sheen, 0.0f, 1.0f},
    {"sheenTint", &MaterialOverrides::sheenTint, &Material::sheenTint, 0.0f, 1.0f},
    {"clearcoat", &MaterialOverrides::clearcoat, &Material::clearcoat, 0.0f, 1.0f},
    {"clearcoatGloss", &MaterialOverrides::clearcoatGloss, &Material::clearcoatGloss, 0.0f, 1.0f},
}};

std::string compact(float x) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", double(x));
  return text;
}

std::string parameterList() {
  std::string list;
  for (const OverrideParameter& p : kParameters) list += (list.empty() ? "" : ", ") + std::string(p.name);
  return list;
}

// The models --shading offers, in ShadingModel's order after Own: those the list of models gives a shading name.
constexpr size_t kShadingChoiceCount = [] {
  size_t count = 0;
  for (const MaterialModelNames& model : kMaterialModelNames) count += model.shadingName != nullptr;
  return count;
}();
static_assert(kShadingChoiceCount == size_t(ShadingModel::Disney),
              "ShadingModel names Own, then each model with a shading name, in the list's order");
constexpr std::array<MaterialModelNames, kShadingChoiceCount> kShadingChoices = [] {
  std::array<MaterialModelNames, kShadingChoiceCount> choices{};
  size_t next = 0;
  for (const MaterialModelNames& model : kMaterialModelNames)
    if (model.shadingName) choices[next++] = model;
  return choices;
}();

// ShadingModel's names in its order.
constexpr std::array<const char*, kShadingChoiceCount + 1> kShadingModelNames = [] {
  std::array<const char*, kShadingChoiceCount + 1> names{"own"};
  for (size_t i = 0; i < kShadingChoiceCount; ++i) names[i + 1] = kShadingChoices[i].shadingName;
  return names;
}();

MaterialType modelType(ShadingModel model) {
  if (model == ShadingModel::Own) throw std::logic_error("no material type for the material's own model");
  return kShadingChoices[size_t(model) - 1].type;
}

// "phong, pbr or disney".
std::string shadingNameList() {
  std::string list;
  for (size_t i = 0; i < kShadingChoices.size(); ++i) {
    if (i > 0) list += i + 1 < kShadingChoices.size() ? ", " : " or ";
    list += kShadingChoices[i].shadingName;
  }
  return list;
}

}  // namespace

std::span<const OverrideParameter> overrideParameters() { return kParameters; }

std::span<const char* const> shadingModelNames() { return kShadingModelNames; }

const char* shadingModelName(ShadingModel model) { return kShadingModelNames[size_t(model)]; }

void setOverride(MaterialOverrides& overrides, const std::string& name, float value) {
  for (const OverrideParameter& p : kParameters) {
    if (name != p.name) continue;
    if (!(value >= p.min && value <= p.max))
      throw std::invalid_argument("override '" + name + "' must lie in [" + compact(p.min) + ", " + compact(p.max) +
                                  "]");
    overrides.*p.field = value;
    return;
  }
  throw std::invalid_argument("unknown override '" + name + "' (known: " + parameterList() + ")");
}

void parseOverride(MaterialOverrides& overrides, const std::string& assignment) {
  size_t eq = assignment.find('=');
  if (eq == std::string::npos) throw std::invalid_argument("override '" + assignment + "' is not name=value");
  std::string name = assignment.substr(0, eq), text = assignment.substr(eq + 1);
  size_t used = 0;
  float value = 0.0f;
  try {
    value = std::stof(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (text.empty() || used != text.size() || !std::isfinite(value))
    throw std::invalid_argument("override '" + name + "' needs a number, not '" + text + "'");
  setOverride(overrides, name, value);
}

ShadingModel parseShadingModel(const std::string& name) {
  for (size_t i = 0; i < kShadingChoices.size(); ++i)
    if (name == kShadingChoices[i].shadingName) return ShadingModel(i + 1);
  throw std::invalid_argument("unknown shading model '" + name + "' (" + shadingNameList() + ")");
}

Material applyOverrides(Material m, const MaterialOverrides& o) {
  // A mix has no parameters of its own to override: the materials it mixes, in the same list, take them.
  if (m.type == MaterialType::Mix || isDeltaModel(m.type)) return m;
  MaterialType target = o.shading == ShadingModel::Own ? m.type : modelType(o.shading);
  bool fromPhong = m.type == MaterialType::BlinnPhong;
  if (fromPhong && target != MaterialType::BlinnPhong) {
    m.roughness = phongExponentToRoughness(m.shininess);
    m.specular = clampf(luminance(m.specularColor) / 0.08f, 0.0f, 1.0f);
    m.metallic = 0.0f;
  }
  for (const OverrideParameter& p : kParameters)
    if (o.*p.field) m.*p.materialField = *(o.*p.field);
  if (target == MaterialType::BlinnPhong) {
    if (!fromPhong) {
      m.specularColor = lerp(m.metallic, Vec3{1, 1, 1} * (0.08f * m.specular), m.baseColor);
      m.baseColor *= 1.0f - m.metallic;
      m.shininess = roughnessToPhongExponent(m.roughness);
    } else {
      if (o.roughness) m.shininess = roughnessToPhongExponent(*o.roughness);
      if (o.specular) m.specularColor = Vec3{1, 1, 1} * (0.08f * *o.specular);
      if (o.metallic) {
        m.specularColor = lerp(*o.metallic, m.specularColor, m.baseColor);
        m.baseColor *= 1.0f - *o.metallic;
      }
    }
  }
  m.type = target;
  return m;
}

void applyOverrides(std::vector<Material>& materials, const MaterialOverrides& overrides) {
  for (Material& m : materials) m = applyOverrides(m, overrides);
}

}  // namespace candela
