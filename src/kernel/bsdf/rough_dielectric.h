#pragma once
#include "kernel/bsdf/bsdf_sample.h"
#include "kernel/bsdf/fresnel.h"
#include "kernel/bsdf/ggx.h"

namespace candela {

// Rough dielectric interface (Walter et al. 2007) with GGX normals sampled by visibility, following pbrt-v4's
// DielectricBxDF. `eta` is the index of the far side (wi.z < 0) over that of wo's side; refracted radiance is
// divided by eta^2 and tinted by `transmissionTint`. Reflection and refraction are chosen by the Fresnel
// reflectance of the sampled microfacet, so the lobe's density integrates to 1 over the sphere.
// An index-matched interface (eta 1: a transmissive material of ior 1 in air) neither reflects nor bends light,
// however rough its microfacets: the lobe is then a delta lobe that continues wo straight on (its half vector
// would be zero, and eval() and pdf() of every pair are 0).
struct RoughDielectric {
  GgxDistribution distribution;
  float eta = 1.5f;
  Vec3 transmissionTint{1, 1, 1};

  CANDELA_FN bool indexMatched() const { return fabsf(eta - 1.0f) < 1e-4f; }

  // The generalised half vector of (wo, wi), facing +z, or false when the pair cannot be connected.
  CANDELA_FN bool halfVector(Vec3 wo, Vec3 wi, Vec3& h) const {
    if (wo.z <= 0.0f || wi.z == 0.0f || indexMatched()) return false;
    bool reflection = wi.z > 0.0f;
    h = reflection ? wo + wi : wi * eta + wo;
    if (dot(h, h) == 0.0f) return false;
    h = normalize(h);
    if (h.z < 0.0f) h = -h;
    // Microfacets seen from behind by either direction contribute nothing.
    return dot(h, wi) * wi.z > 0.0f && dot(h, wo) > 0.0f;
  }

  CANDELA_FN Vec3 eval(Vec3 wo, Vec3 wi) const {
    Vec3 h;
    if (!halfVector(wo, wi, h)) return {0, 0, 0};
    float f = fresnelDielectric(dot(wo, h), eta);
    float dg = distribution.d(h) * distribution.g2(wo, wi);
    if (wi.z > 0.0f) {
      float r = dg * f / (4.0f * wi.z * wo.z);
      return {r, r, r};
    }
    float denom = sqr(dot(wi, h) + dot(wo, h) / eta);
    float t = dg * (1.0f - f) * fabsf(dot(wi, h) * dot(wo, h) / (wi.z * wo.z * denom)) / (eta * eta);
    return transmissionTint * t;
  }

  CANDELA_FN float pdf(Vec3 wo, Vec3 wi) const {
    Vec3 h;
    if (!halfVector(wo, wi, h)) return 0.0f;
    float f = fresnelDielectric(dot(wo, h), eta);
    float visible = distribution.visibleNormalPdf(wo, h);
    if (wi.z > 0.0f) return visible / (4.0f * dot(wo, h)) * f;
    float denom = sqr(dot(wi, h) + dot(wo, h) / eta);
    return visible * fabsf(dot(wi, h)) / denom * (1.0f - f);
  }

  // The half vector, its Fresnel reflectance, D and Lambda(wo) once for both.
  CANDELA_FN BsdfEval evalPdf(Vec3 wo, Vec3 wi) const {
    Vec3 h;
    if (!halfVector(wo, wi, h)) return {};
    float woh = dot(wo, h), wih = dot(wi, h);
    float f = fresnelDielectric(woh, eta);
    float d = distribution.d(h), lambdaO = distribution.lambda(wo);
    float dg = d / (1.0f + lambdaO + distribution.lambda(wi));
    float visible = d * woh / ((1.0f + lambdaO) * wo.z);  // halfVector() made wo.z and wo.h positive
    if (wi.z > 0.0f) {
      float r = dg * f / (4.0f * wi.z * wo.z);
      return {{r, r, r}, visible / (4.0f * woh) * f};
    }
    float denom = sqr(wih + woh / eta);
    float t = dg * (1.0f - f) * fabsf(wih * woh / (wi.z * wo.z * denom)) / (eta * eta);
    return {transmissionTint * t, visible * fabsf(wih) / denom * (1.0f - f)};
  }

  CANDELA_FN BsdfSample sample(Vec3 wo, float uChoice, Vec2 u) const {
    BsdfSample s;
    if (wo.z <= 0.0f) return s;
    if (indexMatched()) {
      s.wi = -wo;
      s.f = transmissionTint / wo.z;
      s.pdf = 1.0f;
      s.eta = eta;
      s.isDelta = true;
      s.valid = true;
      return s;
    }
    Vec3 h = distribution.sampleVisibleNormal(wo, u);
    float f = fresnelDielectric(dot(wo, h), eta);
    if (uChoice < f) {
      s.wi = reflect(wo, h);
      if (s.wi.z <= 0.0f) return s;
    } else {
      if (!refract(wo, h, eta, s.wi) || s.wi.z >= 0.0f) return s;
      s.eta = eta;
    }
    BsdfEval e = evalPdf(wo, s.wi);
    s.f = e.f;
    s.pdf = e.pdf;
    s.valid = s.pdf > 0.0f;
    return s;
  }
};

}  // namespace candela
