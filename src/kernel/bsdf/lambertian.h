#pragma once
#include "core/sampling.h"
#include "kernel/bsdf/bsdf_sample.h"
#include "kernel/material.h"

namespace candela {

// Ideal diffuse reflection, sampled by the cosine.
struct LambertianBsdf {
  Vec3 albedo;

  static constexpr bool kDelta = false;
  CANDELA_FN bool hasTransmission() const { return false; }
  CANDELA_FN static bool transmits(const Material&) { return false; }
  CANDELA_FN static bool orientedByTangent(const Material&) { return false; }
  static constexpr bool kInLeanKernel = true;
  CANDELA_FN static Vec3 guideAlbedo(const Material& m) { return m.baseColor; }
  CANDELA_FN static LambertianBsdf fromMaterial(const Material& m, float /*eta*/, Vec2 /*uv*/) { return {m.baseColor}; }

  CANDELA_FN Vec3 eval(Vec3 wo, Vec3 wi) const {
    return (wo.z > 0.0f && wi.z > 0.0f) ? albedo * kInvPi : Vec3{0, 0, 0};
  }
  CANDELA_FN float pdf(Vec3 wo, Vec3 wi) const { return wo.z > 0.0f ? cosineHemispherePdf(wi.z) : 0.0f; }
  CANDELA_FN BsdfEval evalPdf(Vec3 wo, Vec3 wi) const { return {eval(wo, wi), pdf(wo, wi)}; }
  CANDELA_FN BsdfSample sample(Vec3 wo, float /*uChoice*/, Vec2 u) const {
    BsdfSample s;
    if (wo.z <= 0.0f) return s;
    s.wi = sampleCosineHemisphere(u);
    s.pdf = cosineHemispherePdf(s.wi.z);
    if (s.pdf <= 0.0f) return s;
    s.f = albedo * kInvPi;
    s.valid = true;
    return s;
  }
};

}  // namespace candela
