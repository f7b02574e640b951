#pragma once
#include "kernel/bsdf/bsdf_sample.h"
#include "kernel/bsdf/fresnel.h"
#include "kernel/material.h"

namespace candela {

// Delta lobes. eval() and pdf() are zero for every pair of directions (the chance that a sampled or light
// direction is exactly the reflected one is zero); sample() returns the direction with its discrete
// probability and a value f with f |cos| / pdf equal to the lobe's weight.

// Perfect mirror reflecting `reflectance` of the light.
struct MirrorBsdf {
  Vec3 reflectance;

  static constexpr bool kDelta = true;
  CANDELA_FN bool hasTransmission() const { return false; }
  CANDELA_FN static bool transmits(const Material&) { return false; }
  CANDELA_FN static bool orientedByTangent(const Material&) { return false; }
  static constexpr bool kInLeanKernel = true;
  CANDELA_FN static Vec3 guideAlbedo(const Material& m) { return m.baseColor; }
  CANDELA_FN static MirrorBsdf fromMaterial(const Material& m, float /*eta*/, Vec2 /*uv*/) { return {m.specularColor}; }

  CANDELA_FN Vec3 eval(Vec3, Vec3) const { return {0, 0, 0}; }
  CANDELA_FN float pdf(Vec3, Vec3) const { return 0.0f; }
  CANDELA_FN BsdfEval evalPdf(Vec3, Vec3) const { return {}; }
  CANDELA_FN BsdfSample sample(Vec3 wo, float /*uChoice*/, Vec2 /*u*/) const {
    BsdfSample s;
    if (wo.z <= 0.0f) return s;
    s.wi = {-wo.x, -wo.y, wo.z};
    s.f = reflectance / wo.z;
    s.pdf = 1.0f;
    s.isDelta = true;
    s.valid = true;
    return s;
  }
};

// Smooth dielectric interface: reflects with the Fresnel reflectance, refracts the rest, choosing between the two
// with those probabilities. `eta` is the index of the far side over that of wo's side. Refracted radiance is
// scaled by 1 / eta^2 (radiance is compressed into the denser medium) and tinted by `transmissionTint`.
struct SmoothDielectricBsdf {
  float eta = 1.5f;
  Vec3 transmissionTint{1, 1, 1};

  static constexpr bool kDelta = true;
  CANDELA_FN bool hasTransmission() const { return true; }
  CANDELA_FN static bool transmits(const Material&) { return true; }
  CANDELA_FN static bool orientedByTangent(const Material&) { return false; }
  static constexpr bool kInLeanKernel = true;
  CANDELA_FN static Vec3 guideAlbedo(const Material& m) { return m.baseColor; }
  // Tinted by the square root of the base colour at each crossing, so that a closed object transmits the base
  // colour.
  CANDELA_FN static SmoothDielectricBsdf fromMaterial(const Material& m, float eta, Vec2 /*uv*/) {
    const Vec3 c = m.baseColor;
    return {eta, {sqrtf(fmaxf(0.0f, c.x)), sqrtf(fmaxf(0.0f, c.y)), sqrtf(fmaxf(0.0f, c.z))}};
  }

  CANDELA_FN Vec3 eval(Vec3, Vec3) const { return {0, 0, 0}; }
  CANDELA_FN float pdf(Vec3, Vec3) const { return 0.0f; }
  CANDELA_FN BsdfEval evalPdf(Vec3, Vec3) const { return {}; }
  CANDELA_FN BsdfSample sample(Vec3 wo, float uChoice, Vec2 /*u*/) const {
    BsdfSample s;
    if (wo.z <= 0.0f) return s;
    float r = fresnelDielectric(wo.z, eta);
    s.isDelta = true;
    if (uChoice < r) {
      s.wi = {-wo.x, -wo.y, wo.z};
      s.pdf = r;
      s.f = Vec3{r, r, r} / wo.z;
    } else {
      if (!refract(wo, {0, 0, 1}, eta, s.wi)) return s;  // cannot happen: r = 1 under total reflection
      float t = 1.0f - r;
      s.pdf = t;
      s.eta = eta;
      s.f = transmissionTint * (t / (eta * eta * fabsf(s.wi.z)));
    }
    s.valid = s.pdf > 0.0f;
    return s;
  }
};

}  // namespace candela
