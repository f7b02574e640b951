#pragma once
#include "core/sampling.h"
#include "kernel/bsdf/bsdf_sample.h"
#include "kernel/bsdf/fresnel.h"
#include "kernel/bsdf/ggx.h"
#include "kernel/bsdf/half_vector_reflection.h"

namespace candela {

// Burley 2012's diffuse: Schlick-shaped retro-reflection that grows with roughness, blended towards the
// Hanrahan-Krueger-like "subsurface" shape, plus the sheen term for cloth at grazing angles. Sampled by the
// cosine. Like the original it is not energy conserving: for a white base at roughness 1 it reflects
// 1 + 1/28 of the light arriving along the normal.
struct DisneyDiffuse {
  Vec3 baseColor;
  float roughness = 0.5f;
  float subsurface = 0.0f;
  Vec3 sheenColor{0, 0, 0};  // sheen * mix(white, tint, sheenTint)

  CANDELA_FN Vec3 eval(Vec3 wo, Vec3 wi) const {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return {0, 0, 0};
    Vec3 h = normalize(wo + wi);
    float cosThetaD = dot(wi, h);
    float fl = schlickWeight(wi.z), fv = schlickWeight(wo.z);
    float fd90 = 0.5f + 2.0f * roughness * cosThetaD * cosThetaD;
    float fd = lerp(fl, 1.0f, fd90) * lerp(fv, 1.0f, fd90);
    float fss90 = roughness * cosThetaD * cosThetaD;
    float fss = lerp(fl, 1.0f, fss90) * lerp(fv, 1.0f, fss90);
    float ss = 1.25f * (fss * (1.0f / (wi.z + wo.z) - 0.5f) + 0.5f);
    return baseColor * (kInvPi * lerp(subsurface, fd, ss)) + sheenColor * schlickWeight(cosThetaD);
  }
  CANDELA_FN float pdf(Vec3 wo, Vec3 wi) const { return wo.z > 0.0f ? cosineHemispherePdf(wi.z) : 0.0f; }
  CANDELA_FN BsdfEval evalPdf(Vec3 wo, Vec3 wi) const { return {eval(wo, wi), pdf(wo, wi)}; }
  CANDELA_FN BsdfSample sample(Vec3 wo, float /*uChoice*/, Vec2 u) const {
    BsdfSample s;
    if (wo.z <= 0.0f) return s;
    s.wi = sampleCosineHemisphere(u);
    BsdfEval e = evalPdf(wo, s.wi);
    s.f = e.f;
    s.pdf = e.pdf;
    s.valid = s.pdf > 0.0f;
    return s;
  }
};

// Burley's clearcoat: a fixed-index (f0 = 0.04) layer with the long-tailed GTR1 ("Berry") distribution,
// Smith-GGX masking with alpha 0.25, scaled by `weight` (0.25 clearcoat in the original). Half vectors are
// sampled from D cos(theta_h).
struct DisneyClearcoat {
  float weight = 0.25f;
  float alpha = 0.1f;  // lerp(clearcoatGloss, 0.1, 0.001)

  CANDELA_FN float d(float cosThetaH) const {
    float a2 = alpha * alpha;
    return (a2 - 1.0f) / (kPi * logf(a2) * (1.0f + (a2 - 1.0f) * cosThetaH * cosThetaH));
  }
  CANDELA_FN static float smithG1(float cosTheta) {
    GgxDistribution g{0.25f, 0.25f};
    return g.g1({sqrtf(fmaxf(0.0f, 1.0f - cosTheta * cosTheta)), 0.0f, cosTheta});
  }
  CANDELA_FN Vec3 eval(Vec3 wo, Vec3 wi) const {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return {0, 0, 0};
    Vec3 h = normalize(wo + wi);
    float f = fresnelSchlick(0.04f, dot(wi, h));
    float value = weight * f * d(h.z) * smithG1(wo.z) * smithG1(wi.z) / (4.0f * wo.z * wi.z);
    return {value, value, value};
  }
  CANDELA_FN float pdf(Vec3 wo, Vec3 wi) const {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
    Vec3 h = normalize(wo + wi);
    return d(h.z) * h.z / (4.0f * dot(wo, h));
  }
  CANDELA_FN BsdfEval evalPdf(Vec3 wo, Vec3 wi) const {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return {};
    Vec3 h = normalize(wo + wi);
    float dh = d(h.z);
    float value =
        weight * fresnelSchlick(0.04f, dot(wi, h)) * dh * smithG1(wo.z) * smithG1(wi.z) / (4.0f * wo.z * wi.z);
    return {{value, value, value}, dh * h.z / (4.0f * dot(wo, h))};
  }
  CANDELA_FN BsdfSample sample(Vec3 wo, float /*uChoice*/, Vec2 u) const {
    if (wo.z <= 0.0f) return {};
    float a2 = alpha * alpha;
    float cosThetaH = sqrtf(fmaxf(0.0f, (1.0f - powf(a2, 1.0f - u.x)) / (1.0f - a2)));
    float sinThetaH = sqrtf(fmaxf(0.0f, 1.0f - cosThetaH * cosThetaH));
    float phi = 2.0f * kPi * u.y;
    Vec3 h{sinThetaH * cosf(phi), sinThetaH * sinf(phi), cosThetaH};
    return reflectAboutHalfVector(*this, wo, h);
  }
};

}  // namespace candela
