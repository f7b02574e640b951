#pragma once
#include "core/math.h"

namespace candela {

// Anisotropic GGX (Trowbridge-Reitz) microfacet distribution in the local frame (normal +z, alphaX along x),
// with Smith's masking function and Heitz's sampling of visible normals.
struct GgxDistribution {
  float alphaX = 0.5f, alphaY = 0.5f;

  // Below this the lobe is too narrow for float evaluation to stay meaningful.
  static constexpr float kMinAlpha = 1e-3f;

  CANDELA_FN static float roughnessToAlpha(float roughness) { return fmaxf(kMinAlpha, roughness * roughness); }
  CANDELA_FN static GgxDistribution isotropic(float roughness) {
    float a = roughnessToAlpha(roughness);
    return {a, a};
  }
  // Burley 2012: aspect = sqrt(1 - 0.9 anisotropic) stretches the lobe along the tangent.
  CANDELA_FN static GgxDistribution anisotropic(float roughness, float anisotropic) {
    float aspect = sqrtf(1.0f - 0.9f * clampf(anisotropic, 0.0f, 1.0f));
    float r2 = roughness * roughness;
    return {fmaxf(kMinAlpha, r2 / aspect), fmaxf(kMinAlpha, r2 * aspect)};
  }

  // Density of microfacet normals, normalised so that the integral of d(h) cos(theta_h) is 1.
  CANDELA_FN float d(Vec3 h) const {
    if (h.z <= 0.0f) return 0.0f;
    float e = sqr(h.x / alphaX) + sqr(h.y / alphaY) + h.z * h.z;
    return 1.0f / (kPi * alphaX * alphaY * e * e);
  }

  CANDELA_FN float lambda(Vec3 w) const {
    float cos2 = w.z * w.z;
    if (cos2 == 0.0f) return kInf;
    float tan2Alpha2 = (sqr(alphaX * w.x) + sqr(alphaY * w.y)) / cos2;
    return 0.5f * (sqrtf(1.0f + tan2Alpha2) - 1.0f);
  }
  CANDELA_FN float g1(Vec3 w) const { return 1.0f / (1.0f + lambda(w)); }
  // Height-correlated masking-shadowing (Heitz 2014, eq. 99).
  CANDELA_FN float g2(Vec3 wo, Vec3 wi) const { return 1.0f / (1.0f + lambda(wo) + lambda(wi)); }

  // Density of the normals visible from w (w.z > 0): G1(w) max(0, w.h) D(h) / w.z.
  CANDELA_FN float visibleNormalPdf(Vec3 w, Vec3 h) const {
    float wh = dot(w, h);
    if (w.z <= 0.0f || wh <= 0.0f) return 0.0f;
    return g1(w) * wh * d(h) / w.z;
  }

  // Heitz 2018, "Sampling the GGX Distribution of Visible Normals". Requires w.z > 0.
  CANDELA_FN Vec3 sampleVisibleNormal(Vec3 w, Vec2 u) const {
    Vec3 vh = normalize(Vec3{alphaX * w.x, alphaY * w.y, w.z});
    float lensq = vh.x * vh.x + vh.y * vh.y;
    Vec3 t1 = lensq > 0.0f ? Vec3{-vh.y, vh.x, 0.0f} / sqrtf(lensq) : Vec3{1, 0, 0};
    Vec3 t2 = cross(vh, t1);
    float r = sqrtf(u.x), phi = 2.0f * kPi * u.y;
    float p1 = r * cosf(phi), p2 = r * sinf(phi);
    float s = 0.5f * (1.0f + vh.z);
    p2 = (1.0f - s) * sqrtf(fmaxf(0.0f, 1.0f - p1 * p1)) + s * p2;
    Vec3 nh = t1 * p1 + t2 * p2 + vh * sqrtf(fmaxf(0.0f, 1.0f - p1 * p1 - p2 * p2));
    return normalize(Vec3{alphaX * nh.x, alphaY * nh.y, fmaxf(1e-6f, nh.z)});
  }
};

}  // namespace candela
