#pragma once
#include "core/sampling.h"
#include "kernel/bsdf/fresnel.h"
#include "kernel/bsdf/half_vector_reflection.h"
#include "kernel/bsdf/lambertian.h"
#include "kernel/bsdf/lobe_mixture.h"
#include "kernel/material.h"

namespace candela {

// The Blinn-Phong specular lobe normalised as in Ashikhmin and Shirley 2000 (without their Fresnel term):
//   f = ks (n + 1) / (8 pi) cos^n(theta_h) / ((wo.h) max(cos theta_o, cos theta_i)).
// Half vectors are sampled with density (n + 1) / (2 pi) cos^n(theta_h), so f cos(theta_i) / pdf =
// ks cos(theta_i) / max(cos theta_o, cos theta_i) <= ks: the lobe never reflects more than ks, and it is
// reciprocal.
struct BlinnPhongSpecular {
  Vec3 ks;
  float exponent = 32.0f;

  // Glossy exponents reach 10^5 and more, where cos(theta_h) rounds to 1 in float; working with sin^2(theta_h)
  // keeps the lobe's shape: cos^n = exp(n/2 log(1 - sin^2)).
  CANDELA_FN float halfVectorPdf(Vec3 h) const {
    if (h.z <= 0.0f) return 0.0f;
    float sin2 = fminf(1.0f, h.x * h.x + h.y * h.y);
    return (exponent + 1.0f) * (0.5f * kInvPi) * expf(0.5f * exponent * log1pf(-sin2));
  }
  CANDELA_FN Vec3 eval(Vec3 wo, Vec3 wi) const {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return {0, 0, 0};
    Vec3 h = normalize(wo + wi);
    return ks * (halfVectorPdf(h) / (4.0f * dot(wo, h) * fmaxf(wo.z, wi.z)));
  }
  CANDELA_FN float pdf(Vec3 wo, Vec3 wi) const {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
    Vec3 h = normalize(wo + wi);
    return halfVectorPdf(h) / (4.0f * dot(wo, h));
  }
  // f is the density over max(cos theta_o, cos theta_i), times ks.
  CANDELA_FN BsdfEval evalPdf(Vec3 wo, Vec3 wi) const {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return {};
    Vec3 h = normalize(wo + wi);
    float pdf = halfVectorPdf(h) / (4.0f * dot(wo, h));
    return {ks * (pdf / fmaxf(wo.z, wi.z)), pdf};
  }
  CANDELA_FN BsdfSample sample(Vec3 wo, float /*uChoice*/, Vec2 u) const {
    if (wo.z <= 0.0f) return {};
    // cos(theta_h) = u^(1 / (n + 1)), through sin^2 for precision.
    float sin2ThetaH = u.x > 0.0f ? -expm1f(2.0f * logf(u.x) / (exponent + 1.0f)) : 1.0f;
    float sinThetaH = sqrtf(clampf(sin2ThetaH, 0.0f, 1.0f)), cosThetaH = sqrtf(clampf(1.0f - sin2ThetaH, 0.0f, 1.0f));
    float phi = 2.0f * kPi * u.y;
    Vec3 h{sinThetaH * cosf(phi), sinThetaH * sinf(phi), cosThetaH};
    return reflectAboutHalfVector(*this, wo, h);
  }
};

// Energy-normalised Blinn-Phong: a Lambertian lobe scaled by (1 - max(ks)) under the specular lobe above, so the
// albedo never exceeds 1 for any kd, ks <= 1.
struct BlinnPhongBsdf {
  LambertianBsdf diffuse;
  BlinnPhongSpecular specular;

  CANDELA_FN BlinnPhongBsdf(Vec3 kd, Vec3 ks, float exponent)
      : diffuse{kd * (1.0f - clampf(maxComponent(ks), 0.0f, 1.0f))}, specular{ks, fmaxf(0.0f, exponent)} {}

  static constexpr bool kDelta = false;
  CANDELA_FN bool hasTransmission() const { return false; }
  CANDELA_FN static bool transmits(const Material&) { return false; }
  CANDELA_FN static bool orientedByTangent(const Material&) { return false; }
  static constexpr bool kInLeanKernel = true;
  CANDELA_FN static Vec3 guideAlbedo(const Material& m) { return m.baseColor + m.specularColor; }
  CANDELA_FN static BlinnPhongBsdf fromMaterial(const Material& m, float /*eta*/, Vec2 /*uv*/) {
    return {m.baseColor, m.specularColor, m.shininess};
  }

  CANDELA_FN LobeChoice<2> choice() const {
    return LobeChoice<2>::fromEstimates({luminance(diffuse.albedo), luminance(specular.ks)});
  }
  CANDELA_FN Vec3 eval(Vec3 wo, Vec3 wi) const { return diffuse.eval(wo, wi) + specular.eval(wo, wi); }
  CANDELA_FN float pdf(Vec3 wo, Vec3 wi) const {
    LobeChoice<2> c = choice();
    return c.p[0] * diffuse.pdf(wo, wi) + c.p[1] * specular.pdf(wo, wi);
  }
  CANDELA_FN BsdfEval evalPdf(Vec3 wo, Vec3 wi, const LobeChoice<2>& c) const {
    BsdfEval d = diffuse.evalPdf(wo, wi), s = specular.evalPdf(wo, wi);
    return {d.f + s.f, c.p[0] * d.pdf + c.p[1] * s.pdf};
  }
  CANDELA_FN BsdfEval evalPdf(Vec3 wo, Vec3 wi) const { return evalPdf(wo, wi, choice()); }
  CANDELA_FN BsdfSample sample(Vec3 wo, float uChoice, Vec2 u) const {
    LobeChoice<2> c = choice();
    BsdfSample proposal = c.choose(uChoice) == 0 ? diffuse.sample(wo, 0.0f, u) : specular.sample(wo, 0.0f, u);
    if (!proposal.valid) return proposal;
    return mixtureSample(*this, wo, proposal.wi, 1.0f, c);
  }
};

// Blinn-Phong exponent with about the highlight of a GGX lobe of this roughness (Walter et al. 2007: n = 2 /
// alpha^2 - 2 for Beckmann's alpha, with alpha = roughness^2), and back.
CANDELA_FN float roughnessToPhongExponent(float roughness) {
  float alpha = fmaxf(1e-3f, roughness * roughness);
  return fmaxf(0.0f, 2.0f / (alpha * alpha) - 2.0f);
}
CANDELA_FN float phongExponentToRoughness(float exponent) {
  return sqrtf(sqrtf(2.0f / (fmaxf(0.0f, exponent) + 2.0f)));
}

}  // namespace candela
