#include "scene/loaders/gltf/gltf_specular_glossiness.h"

#include <algorithm>
#include <cmath>

namespace candela {

namespace {

constexpr float kDielectricSpecular = 0.04f;
constexpr float kEpsilon = 1e-6f;

float perceivedBrightness(Vec3 c) { return std::sqrt(0.299f * c.x * c.x + 0.587f * c.y * c.y + 0.114f * c.z * c.z); }

// The metallic value whose blend of a 4% dielectric and a metal reflects `specular` where the diffuse colour
// is `diffuse` (both perceived brightnesses); a quadratic in metallic.
float solveMetallic(float diffuse, float specular, float oneMinusSpecularStrength) {
  if (specular < kDielectricSpecular) return 0.0f;
  const float a = kDielectricSpecular;
  const float b = diffuse * oneMinusSpecularStrength / (1.0f - kDielectricSpecular) + specular - 2.0f * a;
  const float c = kDielectricSpecular - specular;
  const float discriminant = std::max(b * b - 4.0f * a * c, 0.0f);
  return std::clamp((-b + std::sqrt(discriminant)) / (2.0f * a), 0.0f, 1.0f);
}

Vec3 clamp01(Vec3 v) { return {std::clamp(v.x, 0.0f, 1.0f), std::clamp(v.y, 0.0f, 1.0f), std::clamp(v.z, 0.0f, 1.0f)}; }

}  // namespace

MetallicRoughness metallicRoughnessFromSpecularGlossiness(Vec3 diffuse, Vec3 specular, float glossiness) {
  diffuse = clamp01(diffuse);
  specular = clamp01(specular);
  const float oneMinusSpecularStrength = 1.0f - maxComponent(specular);
  MetallicRoughness out;
  out.metallic = solveMetallic(perceivedBrightness(diffuse), perceivedBrightness(specular), oneMinusSpecularStrength);
  const Vec3 fromDiffuse =
      diffuse * (oneMinusSpecularStrength / (1.0f - kDielectricSpecular) / std::max(1.0f - out.metallic, kEpsilon));
  const Vec3 fromSpecular = (specular - Vec3{1, 1, 1} * (kDielectricSpecular * (1.0f - out.metallic))) *
                            (1.0f / std::max(out.metallic, kEpsilon));
  out.baseColor = clamp01(lerp(out.metallic * out.metallic, fromDiffuse, fromSpecular));
  out.roughness = 1.0f - std::clamp(glossiness, 0.0f, 1.0f);
  return out;
}

}  // namespace candela
