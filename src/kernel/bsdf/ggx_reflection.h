#pragma once
#include "kernel/bsdf/bsdf_sample.h"
#include "kernel/bsdf/fresnel.h"
#include "kernel/bsdf/ggx.h"
#include "kernel/bsdf/half_vector_reflection.h"
#include "kernel/bsdf/thin_film.h"

namespace candela {

// Microfacet reflection: GGX normals, height-correlated Smith masking-shadowing, Schlick's Fresnel with a
// coloured normal-incidence reflectance f0, or its mix with an iridescent film's where there is one. Sampled by
// visible normals, so f cos / pdf = F G2 / G1(wo) <= 1.
struct GgxReflection {
  GgxDistribution distribution;
  Vec3 f0;
  ThinFilm film = {};

  CANDELA_FN Vec3 fresnel(float cosTheta) const { return film.fresnel(fresnelSchlick(f0, cosTheta), cosTheta); }

  CANDELA_FN Vec3 eval(Vec3 wo, Vec3 wi) const {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return {0, 0, 0};
    Vec3 h = wo + wi;
    if (dot(h, h) == 0.0f) return {0, 0, 0};
    h = normalize(h);
    float value = distribution.d(h) * distribution.g2(wo, wi) / (4.0f * wo.z * wi.z);
    return fresnel(dot(wi, h)) * value;
  }
  CANDELA_FN float pdf(Vec3 wo, Vec3 wi) const {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
    Vec3 h = wo + wi;
    if (dot(h, h) == 0.0f) return 0.0f;
    h = normalize(h);
    return distribution.visibleNormalPdf(wo, h) / (4.0f * dot(wo, h));
  }
  // D, and Lambda(wo) of G2 and of G1 in the visible-normal density, once: pdf = D G1(wo) / (4 cos_o).
  CANDELA_FN BsdfEval evalPdf(Vec3 wo, Vec3 wi) const {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return {};
    Vec3 h = wo + wi;
    if (dot(h, h) == 0.0f) return {};
    h = normalize(h);
    float d = distribution.d(h), lambdaO = distribution.lambda(wo);
    float value = d / ((1.0f + lambdaO + distribution.lambda(wi)) * 4.0f * wo.z * wi.z);
    float pdf = dot(wo, h) > 0.0f ? d / ((1.0f + lambdaO) * 4.0f * wo.z) : 0.0f;
    return {fresnel(dot(wi, h)) * value, pdf};
  }
  CANDELA_FN BsdfSample sample(Vec3 wo, float /*uChoice*/, Vec2 u) const {
    if (wo.z <= 0.0f) return {};
    return reflectAboutHalfVector(*this, wo, distribution.sampleVisibleNormal(wo, u));
  }
};

}  // namespace candela
