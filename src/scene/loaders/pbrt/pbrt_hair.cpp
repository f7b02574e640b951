#include "scene/loaders/pbrt/pbrt_hair.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "kernel/bsdf/hair.h"

namespace candela {

namespace {

bool nonNegative(Vec3 v) { return isFinite(v) && v.x >= 0.0f && v.y >= 0.0f && v.z >= 0.0f; }

}  // namespace

Material pbrtHairMaterial(const PbrtParameters& params, PbrtTextures& textures, PbrtContext& context) {
  // One value of a parameter that pbrt lets vary over the fibre; candela's hair takes one per material.
  auto colour = [&](const std::string& name, Vec3 fallback) {
    const PbrtTexture t = textures.value(params, name, fallback);
    if (t.image != kNoTexture)
      context.warn("hair texture " + name, "a textured hair '" + name + "' is rendered with its mean");
    return textures.meanColour(t);
  };
  auto number = [&](const std::string& name, float fallback) { return colour(name, {fallback, fallback, fallback}).x; };
  auto given = [&](const char* parameter) { return params.find(parameter) != nullptr; };

  Material m;
  m.type = MaterialType::Hair;
  m.ior = number("eta", 1.55f);
  if (!(m.ior > 0.0f) || !std::isfinite(m.ior)) params.fail("hair: 'eta' must be finite and positive");
  m.roughness = number("beta_m", 0.3f);
  if (!(m.roughness > 0.0f && m.roughness <= 1.0f)) params.fail("hair: 'beta_m' must lie in (0, 1]");
  m.azimuthalRoughness = number("beta_n", 0.3f);
  if (!(m.azimuthalRoughness > 0.0f && m.azimuthalRoughness <= 1.0f)) params.fail("hair: 'beta_n' must lie in (0, 1]");
  m.scaleTilt = number("alpha", 2.0f);
  if (!std::isfinite(m.scaleTilt)) params.fail("hair: 'alpha' must be finite");

  const char* reflectanceName = given("reflectance") ? "reflectance" : "color";
  const bool hasReflectance = given(reflectanceName);
  const bool hasMelanin = given("eumelanin") || given("pheomelanin");
  auto ignored = [&](const std::string& what, const std::string& form) {
    context.warn("hair " + what + " ignored", "a hair '" + what + "' is ignored since '" + form + "' is given");
  };
  if (given("sigma_a")) {
    if (hasReflectance) ignored(reflectanceName, "sigma_a");
    if (hasMelanin) ignored("eumelanin/pheomelanin", "sigma_a");
    m.fibreAbsorption = colour("sigma_a", {});
    if (!nonNegative(m.fibreAbsorption)) params.fail("hair: 'sigma_a' must be finite and not negative");
  } else if (hasReflectance) {
    if (hasMelanin) ignored("eumelanin/pheomelanin", reflectanceName);
    const Vec3 c = colour(reflectanceName, {});
    if (!nonNegative(c)) params.fail(std::string("hair: '") + reflectanceName + "' must be finite and not negative");
    // pbrt clamps the colour to [0, 1]; a black channel absorbs all light that enters, here as an absorption
    // large enough that none comes out.
    const float least = std::numeric_limits<float>::min();
    const Vec3 clamped{std::clamp(c.x, least, 1.0f), std::clamp(c.y, least, 1.0f), std::clamp(c.z, least, 1.0f)};
    m.fibreAbsorption = HairBsdf::absorptionOfReflectance(clamped, std::clamp(m.azimuthalRoughness, 0.01f, 1.0f));
  } else if (hasMelanin) {
    const float eumelanin = number("eumelanin", 0.0f), pheomelanin = number("pheomelanin", 0.0f);
    if (!(eumelanin >= 0.0f && pheomelanin >= 0.0f) || !std::isfinite(eumelanin) || !std::isfinite(pheomelanin))
      params.fail("hair: 'eumelanin' and 'pheomelanin' must be finite and not negative");
    m.fibreAbsorption = HairBsdf::absorptionOfMelanin(eumelanin, pheomelanin);
    if (!isFinite(m.fibreAbsorption)) params.fail("hair: its melanin concentrations overflow");
  } else {
    m.fibreAbsorption = HairBsdf::absorptionOfMelanin(1.3f, 0.0f);  // pbrt-v4's brown hair
  }
  return m;
}

}  // namespace candela
