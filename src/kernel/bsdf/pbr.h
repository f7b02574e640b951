#pragma once
#include "core/sampling.h"
#include "kernel/bsdf/ggx_reflection.h"
#include "kernel/bsdf/lobe_mixture.h"
#include "kernel/material.h"

namespace candela {

// glTF 2.0's metallic-roughness BRDF (specification, appendix B), with one change for energy conservation:
//   f = (1 - metallic) (1 - F_d(cos_o)) (1 - F_d(cos_i)) baseColor / pi + F(wo.h) D G2 / (4 cos_o cos_i),
// with F Schlick's Fresnel at f0 = lerp(metallic, 0.08 specular, baseColor) (0.04 at the default specular 0.5)
// and F_d its dielectric part. Because Schlick's form is linear in f0, the specular term equals glTF's
// mix(dielectric_brdf, metal_brdf, metallic). glTF weights the diffuse term by 1 - F_d(wo.h) instead, which
// leaves it nearly whole at grazing view while the specular lobe reflects almost everything: a smooth white
// dielectric then reflects 1.8 times the light arriving at 89 degrees. Weighting by the Fresnel transmittance
// into and out of the surface (as Shirley et al. 1997 and Ashikhmin-Shirley 2000 do) keeps the albedo below 1
// and the BRDF reciprocal. The diffuse term is sampled by the cosine, the specular by GGX visible normals,
// combined as a mixture (see lobe_mixture.h).
//
// KHR_materials_iridescence's film (iridescence > 0; thin_film.h) replaces the specular lobe's Fresnel term by its
// mix with the film's, and F_d by its mix with the brightest channel of the film's reflectance over the dielectric
// base, as the extension's rgb_mix weights the base by 1 - max(F): the diffuse term never gains from a colour the
// film reflects less of.
struct PbrBsdf {
  Vec3 diffuseColor;  // (1 - metallic) baseColor
  float dielectricF0 = 0.04f;
  GgxReflection specular;

  CANDELA_FN PbrBsdf(Vec3 baseColor, float metallic, float roughness, float specularLevel, float iridescence = 0.0f,
                     float iridescenceIor = 1.3f, float iridescenceThickness = 0.0f) {
    metallic = clampf(metallic, 0.0f, 1.0f);
    diffuseColor = baseColor * (1.0f - metallic);
    dielectricF0 = 0.08f * clampf(specularLevel, 0.0f, 1.0f);
    const Vec3 dielectric{dielectricF0, dielectricF0, dielectricF0};
    specular = {GgxDistribution::isotropic(roughness), lerp(metallic, dielectric, baseColor)};
    if (iridescence > 0.0f)
      specular.film =
          ThinFilm::over(iridescence, iridescenceIor, iridescenceThickness, metallic, dielectric, baseColor);
  }

  static constexpr bool kDelta = false;
  CANDELA_FN bool hasTransmission() const { return false; }
  CANDELA_FN static bool transmits(const Material&) { return false; }
  CANDELA_FN static bool orientedByTangent(const Material&) { return false; }
  static constexpr bool kInLeanKernel = true;
  CANDELA_FN static Vec3 guideAlbedo(const Material& m) { return m.baseColor; }
  CANDELA_FN static PbrBsdf fromMaterial(const Material& m, float /*eta*/, Vec2 /*uv*/) {
    return {m.baseColor, m.metallic, m.roughness, m.specular, m.iridescence, m.iridescenceIor, m.iridescenceThickness};
  }

  // The dielectric base's reflectance F_d at cosTheta, which the diffuse term does not see.
  CANDELA_FN float dielectricFresnel(float cosTheta) const {
    const float schlick = fresnelSchlick(dielectricF0, cosTheta);
    const ThinFilm& film = specular.film;
    return film.present() ? lerp(film.weight, schlick, maxComponent(film.overDielectric(cosTheta))) : schlick;
  }
  CANDELA_FN Vec3 evalDiffuse(Vec3 wo, Vec3 wi) const {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return {0, 0, 0};
    return diffuseColor * ((1.0f - dielectricFresnel(wo.z)) * (1.0f - dielectricFresnel(wi.z)) * kInvPi);
  }
  CANDELA_FN LobeChoice<2> choice(Vec3 wo) const {
    return LobeChoice<2>::fromEstimates({luminance(diffuseColor) * (1.0f - fresnelSchlick(dielectricF0, wo.z)),
                                         luminance(fresnelSchlick(specular.f0, wo.z))});
  }
  CANDELA_FN Vec3 eval(Vec3 wo, Vec3 wi) const { return evalDiffuse(wo, wi) + specular.eval(wo, wi); }
  CANDELA_FN float pdf(Vec3 wo, Vec3 wi) const {
    if (wo.z <= 0.0f) return 0.0f;
    LobeChoice<2> c = choice(wo);
    return c.p[0] * cosineHemispherePdf(wi.z) + c.p[1] * specular.pdf(wo, wi);
  }
  // With the lobe choice for wo (wo.z > 0) given.
  CANDELA_FN BsdfEval evalPdf(Vec3 wo, Vec3 wi, const LobeChoice<2>& c) const {
    BsdfEval s = specular.evalPdf(wo, wi);
    return {evalDiffuse(wo, wi) + s.f, c.p[0] * cosineHemispherePdf(wi.z) + c.p[1] * s.pdf};
  }
  CANDELA_FN BsdfEval evalPdf(Vec3 wo, Vec3 wi) const {
    if (wo.z <= 0.0f) return {};
    return evalPdf(wo, wi, choice(wo));
  }
  CANDELA_FN BsdfSample sample(Vec3 wo, float uChoice, Vec2 u) const {
    if (wo.z <= 0.0f) return {};
    LobeChoice<2> c = choice(wo);
    Vec3 wi;
    if (c.choose(uChoice) == 0) {
      wi = sampleCosineHemisphere(u);
    } else {
      BsdfSample s = specular.sample(wo, 0.0f, u);
      if (!s.valid) return s;
      wi = s.wi;
    }
    return mixtureSample(*this, wo, wi, 1.0f, c);
  }
};

}  // namespace candela
