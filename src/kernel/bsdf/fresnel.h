#pragma once
#include "core/math.h"

namespace candela {

// (1 - cos)^5, the weight of Schlick's approximation.
CANDELA_FN float schlickWeight(float cosTheta) {
  float m = clampf(1.0f - cosTheta, 0.0f, 1.0f);
  float m2 = m * m;
  return m2 * m2 * m;
}

CANDELA_FN Vec3 fresnelSchlick(Vec3 f0, float cosTheta) { return lerp(schlickWeight(cosTheta), f0, Vec3{1, 1, 1}); }
CANDELA_FN float fresnelSchlick(float f0, float cosTheta) { return lerp(schlickWeight(cosTheta), f0, 1.0f); }

// Unpolarised Fresnel reflectance of a dielectric interface. `eta` is the index of the far side over the index
// of the side cosThetaI is measured on; a negative cosine means the light arrives from the far side.
CANDELA_FN float fresnelDielectric(float cosThetaI, float eta) {
  cosThetaI = clampf(cosThetaI, -1.0f, 1.0f);
  if (cosThetaI < 0.0f) {
    eta = 1.0f / eta;
    cosThetaI = -cosThetaI;
  }
  float sin2ThetaT = (1.0f - cosThetaI * cosThetaI) / (eta * eta);
  if (sin2ThetaT >= 1.0f) return 1.0f;  // total internal reflection
  float cosThetaT = sqrtf(fmaxf(0.0f, 1.0f - sin2ThetaT));
  float rParallel = (eta * cosThetaI - cosThetaT) / (eta * cosThetaI + cosThetaT);
  float rPerpendicular = (cosThetaI - eta * cosThetaT) / (cosThetaI + eta * cosThetaT);
  return 0.5f * (rParallel * rParallel + rPerpendicular * rPerpendicular);
}

CANDELA_FN Vec3 reflect(Vec3 wo, Vec3 n) { return n * (2.0f * dot(wo, n)) - wo; }

// Refracts wo (pointing away from the surface, on the side n points to) through a surface whose far side has
// `eta` times the index of wo's side. Returns false on total internal reflection.
CANDELA_FN bool refract(Vec3 wo, Vec3 n, float eta, Vec3& wt) {
  float cosThetaI = dot(n, wo);
  float sin2ThetaT = fmaxf(0.0f, 1.0f - cosThetaI * cosThetaI) / (eta * eta);
  if (sin2ThetaT >= 1.0f) return false;
  float cosThetaT = sqrtf(1.0f - sin2ThetaT);
  wt = -wo / eta + n * (cosThetaI / eta - cosThetaT);
  return true;
}

}  // namespace candela
