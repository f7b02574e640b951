#include "scene/loaders/pbrt/pbrt_subsurface.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "scene/loaders/pbrt/pbrt_scattering_presets.h"
#include "scene/subsurface_albedo.h"

namespace candela {

namespace {

bool nonNegative(Vec3 v) { return isFinite(v) && v.x >= 0.0f && v.y >= 0.0f && v.z >= 0.0f; }

}  // namespace

Medium pbrtSubsurfaceInterior(const PbrtParameters& params, PbrtTextures& textures, PbrtContext& context) {
  // One colour of a parameter that pbrt lets vary over the surface; candela's medium is one for the whole object.
  auto colour = [&](const char* name, Vec3 fallback) {
    const PbrtTexture t = textures.value(params, name, fallback);
    if (t.image != kNoTexture)
      context.warn(std::string("subsurface texture ") + name,
                   std::string("a textured subsurface '") + name + "' is rendered with its mean colour");
    const Vec3 v = textures.meanColour(t);
    if (!nonNegative(v)) params.fail(std::string("subsurface: '") + name + "' must be finite and not negative");
    return v;
  };
  const float scale = params.getFloat("scale", 1.0f);
  if (!(scale > 0.0f) || !std::isfinite(scale)) params.fail("subsurface: 'scale' must be finite and positive");
  float g = params.getFloat("g", 0.0f);
  if (!(std::fabs(g) < 1.0f)) params.fail("subsurface: 'g' must lie between -1 and 1");

  Medium m;
  const std::string name = params.getString("name", "");
  // Looked up only where the form reads them: a parameter that pbrt would ignore is reported unused.
  auto given = [&](const char* parameter) { return params.find(parameter) != nullptr; };
  if (!name.empty()) {
    const std::optional<ScatteringPreset> preset = pbrtScatteringPreset(name);
    if (!preset) params.fail("subsurface: no measured medium is named '" + name + "'");
    if (g != 0.0f)
      context.warn("subsurface named g",
                   "a subsurface 'g' is ignored with a named medium, whose scattering is "
                   "measured as isotropic (as in pbrt-v4)");
    g = 0.0f;
    m.sigmaA = preset->sigmaA * scale;
    m.sigmaS = preset->sigmaS * scale;
  } else if (given("sigma_a") || given("sigma_s")) {
    if (!given("sigma_a") || !given("sigma_s"))
      params.fail("subsurface: 'sigma_a' and 'sigma_s' must be given together");
    m.sigmaA = colour("sigma_a", {}) * scale;
    m.sigmaS = colour("sigma_s", {}) * scale;
  } else if (given("reflectance")) {
    const Vec3 reflectance = colour("reflectance", {});
    const Vec3 meanFreePath = colour("mfp", {1, 1, 1}) * scale;
    if (!(meanFreePath.x > 0.0f && meanFreePath.y > 0.0f && meanFreePath.z > 0.0f))
      params.fail("subsurface: 'mfp' must be positive");
    if (maxComponent(reflectance) > 1.0f)
      context.warn("subsurface reflectance above 1", "a subsurface 'reflectance' above 1 is taken as 1");
    m = subsurfaceMediumFromReflectance(reflectance, meanFreePath, g);
  } else {
    m.sigmaA = Vec3{0.0011f, 0.0024f, 0.014f} * scale;
    m.sigmaS = Vec3{2.55f, 3.21f, 3.77f} * scale;
  }
  m.g = g;
  m.subsurface = 1;
  if (!nonNegative(m.sigmaA) || !nonNegative(m.sigmaS)) params.fail("subsurface: its coefficients overflow");
  return m;
}

}  // namespace candela
