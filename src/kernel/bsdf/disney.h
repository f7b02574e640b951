#pragma once
#include "kernel/bsdf/disney_lobes.h"
#include "kernel/bsdf/ggx_reflection.h"
#include "kernel/bsdf/lobe_mixture.h"
#include "kernel/bsdf/rough_dielectric.h"
#include "kernel/material.h"

namespace candela {

// Burley's principled BSDF (2012) with the specular transmission of the 2015 extension, arranged as Blender's
// first Principled BSDF arranges it: with T = specTrans (1 - metallic),
//   f = (1 - metallic)(1 - specTrans) diffuse_and_sheen + (1 - T) specular + T glass + clearcoat.
// The specular lobe's normal-incidence reflectance comes from `specular` (0.08 specular, tinted towards the base
// hue by specularTint, towards the base colour by metallic); the glass lobe uses `ior` and is tinted by the
// square root of the base colour per crossing, so a closed object transmits the base colour. An iridescent film
// (KHR_materials_iridescence, thin_film.h) changes the specular lobe's Fresnel term only: the extension ignores
// the interface to a clearcoat above it, and the glass lobe keeps the dielectric's Fresnel.
struct DisneyBsdf {
  DisneyDiffuse diffuse;
  GgxReflection specular;
  RoughDielectric glass;
  DisneyClearcoat clearcoat;
  float diffuseWeight = 0.0f, specularWeight = 0.0f, glassWeight = 0.0f;

  // `eta` is the relative index across the surface seen from wo (ior entering, 1 / ior leaving).
  CANDELA_FN DisneyBsdf(const Material& m, float eta) {
    Vec3 base = m.baseColor;
    float metallic = clampf(m.metallic, 0.0f, 1.0f), specTrans = clampf(m.specTrans, 0.0f, 1.0f);
    float lum = luminance(base);
    Vec3 tint = lum > 0.0f ? base / lum : Vec3{1, 1, 1};
    Vec3 sheenColor = lerp(clampf(m.sheenTint, 0.0f, 1.0f), Vec3{1, 1, 1}, tint) * fmaxf(0.0f, m.sheen);
    diffuse = {base, m.roughness, clampf(m.subsurface, 0.0f, 1.0f), sheenColor};

    GgxDistribution lobe = GgxDistribution::anisotropic(m.roughness, m.anisotropic);
    Vec3 dielectricF0 =
        lerp(clampf(m.specularTint, 0.0f, 1.0f), Vec3{1, 1, 1}, tint) * (0.08f * fmaxf(0.0f, m.specular));
    specular = {lobe, lerp(metallic, dielectricF0, base)};
    if (m.iridescence > 0.0f)
      specular.film =
          ThinFilm::over(m.iridescence, m.iridescenceIor, m.iridescenceThickness, metallic, dielectricF0, base);
    Vec3 sqrtBase{sqrtf(fmaxf(0.0f, base.x)), sqrtf(fmaxf(0.0f, base.y)), sqrtf(fmaxf(0.0f, base.z))};
    glass = {lobe, eta, sqrtBase};
    clearcoat = {0.25f * clampf(m.clearcoat, 0.0f, 1.0f), lerp(clampf(m.clearcoatGloss, 0.0f, 1.0f), 0.1f, 0.001f)};

    diffuseWeight = (1.0f - metallic) * (1.0f - specTrans);
    glassWeight = (1.0f - metallic) * specTrans;
    specularWeight = 1.0f - glassWeight;
  }

  static constexpr bool kDelta = false;
  CANDELA_FN bool hasTransmission() const { return glassWeight > 0.0f; }
  CANDELA_FN static bool transmits(const Material& m) { return m.specTrans > 0.0f; }
  CANDELA_FN static bool orientedByTangent(const Material& m) { return m.anisotropic > 0.0f; }
  static constexpr bool kInLeanKernel = true;
  CANDELA_FN static Vec3 guideAlbedo(const Material& m) { return m.baseColor; }
  CANDELA_FN static DisneyBsdf fromMaterial(const Material& m, float eta, Vec2 /*uv*/) { return DisneyBsdf(m, eta); }

  // Lobes: 0 diffuse and sheen, 1 specular, 2 glass, 3 clearcoat.
  CANDELA_FN LobeChoice<4> choice(Vec3 wo) const {
    float diffuseGuess = luminance(diffuse.baseColor) + 0.5f * luminance(diffuse.sheenColor);
    float glassF = fresnelDielectric(wo.z, glass.eta);
    float estimates[4] = {
        diffuseWeight * diffuseGuess,
        specularWeight * luminance(fresnelSchlick(specular.f0, wo.z)),
        glassWeight * (glassF + (1.0f - glassF) * luminance(glass.transmissionTint)),
        clearcoat.weight * fresnelSchlick(0.04f, wo.z),
    };
    return LobeChoice<4>::fromEstimates(estimates);
  }

  CANDELA_FN Vec3 eval(Vec3 wo, Vec3 wi) const {
    Vec3 f{0, 0, 0};
    if (diffuseWeight > 0.0f) f += diffuse.eval(wo, wi) * diffuseWeight;
    if (specularWeight > 0.0f) f += specular.eval(wo, wi) * specularWeight;
    if (glassWeight > 0.0f) f += glass.eval(wo, wi) * glassWeight;
    if (clearcoat.weight > 0.0f) f += clearcoat.eval(wo, wi);
    return f;
  }
  CANDELA_FN float pdf(Vec3 wo, Vec3 wi) const {
    LobeChoice<4> c = choice(wo);
    float p = 0.0f;
    if (c.p[0] > 0.0f) p += c.p[0] * diffuse.pdf(wo, wi);
    if (c.p[1] > 0.0f) p += c.p[1] * specular.pdf(wo, wi);
    if (c.p[2] > 0.0f) p += c.p[2] * glass.pdf(wo, wi);
    if (c.p[3] > 0.0f) p += c.p[3] * clearcoat.pdf(wo, wi);
    return p;
  }
  // eval() and pdf() in one, each lobe evaluated once, with the lobe choice for wo given.
  CANDELA_FN BsdfEval evalPdf(Vec3 wo, Vec3 wi, const LobeChoice<4>& c) const {
    BsdfEval sum;
    auto add = [&](const BsdfEval& lobe, float weight, float p) {
      if (weight > 0.0f) sum.f += lobe.f * weight;
      if (p > 0.0f) sum.pdf += p * lobe.pdf;
    };
    if (diffuseWeight > 0.0f || c.p[0] > 0.0f) add(diffuse.evalPdf(wo, wi), diffuseWeight, c.p[0]);
    if (specularWeight > 0.0f || c.p[1] > 0.0f) add(specular.evalPdf(wo, wi), specularWeight, c.p[1]);
    if (glassWeight > 0.0f || c.p[2] > 0.0f) add(glass.evalPdf(wo, wi), glassWeight, c.p[2]);
    if (clearcoat.weight > 0.0f || c.p[3] > 0.0f)
      add(clearcoat.evalPdf(wo, wi), clearcoat.weight > 0.0f ? 1.0f : 0.0f, c.p[3]);
    return sum;
  }
  CANDELA_FN BsdfEval evalPdf(Vec3 wo, Vec3 wi) const { return evalPdf(wo, wi, choice(wo)); }
  CANDELA_FN BsdfSample sample(Vec3 wo, float uChoice, Vec2 u) const {
    LobeChoice<4> c = choice(wo);
    int lobe = c.choose(uChoice);
    // The remainder of uChoice within the chosen lobe's share drives the glass lobe's reflect/refract choice.
    float below = 0.0f;
    for (int i = 0; i < lobe; ++i) below += c.p[i];
    float uLobe = clampf((uChoice - below) / c.p[lobe], 0.0f, 0.99999994f);
    BsdfSample proposal;
    switch (lobe) {
      case 0: proposal = diffuse.sample(wo, uLobe, u); break;
      case 1: proposal = specular.sample(wo, uLobe, u); break;
      case 2: proposal = glass.sample(wo, uLobe, u); break;
      default: proposal = clearcoat.sample(wo, uLobe, u); break;
    }
    if (!proposal.valid) return proposal;
    if (proposal.isDelta) {
      // The index-matched glass lobe: no other lobe has a value in exactly that direction.
      proposal.f *= glassWeight;
      proposal.pdf *= c.p[lobe];
      return proposal;
    }
    return mixtureSample(*this, wo, proposal.wi, glass.eta, c);
  }
};

}  // namespace candela
