#pragma once
#include "core/sampling.h"
#include "kernel/bsdf/bsdf_sample.h"
#include "kernel/material.h"

namespace candela {

// pbrt-v4's DiffuseTransmissionBxDF: Lambertian reflection of `reflectance` on wo's side and Lambertian
// transmission of `transmittance` to the other, the same seen from either side (a leaf, a lamp shade, paper). A
// sample picks reflection or transmission in proportion to their largest channels, then a cosine-distributed
// direction on that side; a surface that does neither samples nothing and has density 0. Transmission does not bend
// light: its eta is 1.
struct DiffuseTransmissionBsdf {
  Vec3 reflectance;
  Vec3 transmittance;

  static constexpr bool kDelta = false;
  CANDELA_FN bool hasTransmission() const { return maxComponent(transmittance) > 0.0f; }
  CANDELA_FN static bool transmits(const Material& m) { return maxComponent(m.transmittance) > 0.0f; }
  CANDELA_FN static bool orientedByTangent(const Material&) { return false; }
  static constexpr bool kInLeanKernel = false;
  CANDELA_FN static Vec3 guideAlbedo(const Material& m) { return m.baseColor + m.transmittance; }
  CANDELA_FN static DiffuseTransmissionBsdf fromMaterial(const Material& m, float /*eta*/, Vec2 /*uv*/) {
    return {m.baseColor, m.transmittance};
  }

  CANDELA_FN Vec3 eval(Vec3 wo, Vec3 wi) const {
    if (wo.z <= 0.0f || wi.z == 0.0f) return {0, 0, 0};
    return (wi.z > 0.0f ? reflectance : transmittance) * kInvPi;
  }
  CANDELA_FN float pdf(Vec3 wo, Vec3 wi) const {
    const float pr = maxComponent(reflectance), pt = maxComponent(transmittance);
    if (wo.z <= 0.0f || wi.z == 0.0f || !(pr + pt > 0.0f)) return 0.0f;
    return (wi.z > 0.0f ? pr : pt) / (pr + pt) * cosineHemispherePdf(fabsf(wi.z));
  }
  CANDELA_FN BsdfEval evalPdf(Vec3 wo, Vec3 wi) const { return {eval(wo, wi), pdf(wo, wi)}; }
  CANDELA_FN BsdfSample sample(Vec3 wo, float uChoice, Vec2 u) const {
    BsdfSample s;
    const float pr = maxComponent(reflectance), pt = maxComponent(transmittance);
    if (wo.z <= 0.0f || !(pr + pt > 0.0f)) return s;
    const bool reflect = uChoice < pr / (pr + pt);
    s.wi = sampleCosineHemisphere(u);
    if (!reflect) s.wi.z = -s.wi.z;
    s.pdf = (reflect ? pr : pt) / (pr + pt) * cosineHemispherePdf(fabsf(s.wi.z));
    if (!(s.pdf > 0.0f)) return s;
    s.f = (reflect ? reflectance : transmittance) * kInvPi;
    s.valid = true;
    return s;
  }
};

}  // namespace candela
