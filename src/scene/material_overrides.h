#pragma once
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "kernel/material.h"

namespace candela {

// The shading model every non-delta material is rendered with: its own, or one chosen for the whole scene.
enum class ShadingModel { Own, BlinnPhong, Pbr, Disney };

// Scene-wide material settings: a shading-model switch and parameter values that replace every material's own.
// The command line sets them with --shading and --override; a viewer binds the same fields to its controls and
// re-applies them to the scene's original materials whenever one changes.
struct MaterialOverrides {
  ShadingModel shading = ShadingModel::Own;
  std::optional<float> specular, roughness, metallic, subsurface, specularTint, sheen, sheenTint, clearcoat,
      clearcoatGloss;
};

// One overridable parameter: its name on the command line and its valid range.
struct OverrideParameter {
  const char* name;
  std::optional<float> MaterialOverrides::*field;
  float Material::*materialField;
  float min, max;
};
std::span<const OverrideParameter> overrideParameters();

// Sets `name` to `value`; throws std::invalid_argument naming the problem for an unknown name or a value out of
// range.
void setOverride(MaterialOverrides& overrides, const std::string& name, float value);
// Parses "name=value" and sets it, with the same errors.
void parseOverride(MaterialOverrides& overrides, const std::string& assignment);
// "phong", "pbr" or "disney"; throws std::invalid_argument otherwise.
ShadingModel parseShadingModel(const std::string& name);
// The name of each ShadingModel, in its order: "own", then those parseShadingModel takes.
std::span<const char* const> shadingModelNames();
const char* shadingModelName(ShadingModel model);

// The material as rendered under `overrides`. Mirrors and smooth glass keep their model and parameters: they
// have no lobes to switch. Switching to Blinn-Phong derives kd = (1 - metallic) baseColor, ks = lerp(metallic,
// 0.08 specular, baseColor) and the exponent from roughness (roughnessToPhongExponent); switching from it derives
// roughness from the exponent and specular from ks. On a Blinn-Phong material, overriding roughness sets the
// exponent, specular sets ks to grey 0.08 specular, metallic moves ks towards and kd away from the base colour.
Material applyOverrides(Material material, const MaterialOverrides& overrides);
void applyOverrides(std::vector<Material>& materials, const MaterialOverrides& overrides);

}  // namespace candela
