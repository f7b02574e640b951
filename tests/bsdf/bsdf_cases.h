#pragma once
#include <cmath>
#include <functional>
#include <string>
#include <tuple>
#include <vector>

#include "kernel/bsdf/bsdf.h"

namespace candela::test {

// One lobe or model in its local frame, as the BSDF tests see it: wo on the +z side, wi anywhere.
struct BsdfCase {
  std::string name;
  std::function<Vec3(Vec3, Vec3)> eval;
  std::function<float(Vec3, Vec3)> pdf;
  std::function<BsdfEval(Vec3, Vec3)> evalPdf;
  std::function<BsdfSample(Vec3, float, Vec2)> sample;
  bool reciprocal = true;  // f(wo, wi) == f(wi, wo) for wi on wo's side
  bool refracts = true;    // its transmission bends light (a sample's eta is not 1)
};

template <class Model>
BsdfCase makeCase(std::string name, const Model& model, bool reciprocal = true) {
  return {std::move(name),
          [model](Vec3 wo, Vec3 wi) { return model.eval(wo, wi); },
          [model](Vec3 wo, Vec3 wi) { return model.pdf(wo, wi); },
          [model](Vec3 wo, Vec3 wi) { return model.evalPdf(wo, wi); },
          [model](Vec3 wo, float uc, Vec2 u) { return model.sample(wo, uc, u); },
          reciprocal};
}

inline Vec3 directionAt(float thetaDegrees, float phiDegrees = 0.0f) {
  float t = thetaDegrees * kPi / 180.0f, p = phiDegrees * kPi / 180.0f;
  return {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
}

inline Material disneyMaterial(float roughness) {
  Material m;
  m.type = MaterialType::Disney;
  m.baseColor = {0.8f, 0.6f, 0.4f};
  m.roughness = roughness;
  return m;
}

// Directional albedo (luminance) by deterministic midpoint quadrature of eval() |cos| over the hemisphere in (cos
// theta, phi): independent of every sampling routine. Only for lobes smooth enough for the grid (roughness >= 0.3).
inline double albedoByQuadrature(const BsdfCase& c, Vec3 wo) {
  constexpr int kN = 400;
  double sum = 0.0;
  for (int i = 0; i < kN; ++i)
    for (int j = 0; j < 2 * kN; ++j) {
      double mu = (i + 0.5) / kN, phi = 2 * kPi * (j + 0.5) / (2 * kN);
      double st = std::sqrt(1 - mu * mu);
      Vec3 wi{float(st * std::cos(phi)), float(st * std::sin(phi)), float(mu)};
      sum += luminance(c.eval(wo, wi)) * mu;
    }
  return sum * (1.0 / kN) * (2 * kPi / (2 * kN));
}

// Every non-delta lobe and model at one roughness, with wo on the +z side.
inline std::vector<BsdfCase> casesAtRoughness(float r) {
  std::vector<BsdfCase> cases;
  Vec3 color{0.8f, 0.6f, 0.4f};
  // The chi-square support integrates each cell by adaptive quadrature, which cannot find a peak narrower than
  // a few hundredths of a radian when a smooth lobe dominates the cell: Blinn-Phong at roughness 0.05 (exponent
  // 3.2e5, a 0.003-radian lobe) is tested at the exponent 1000 (0.04 radians) instead.
  float exponent = std::fmin(roughnessToPhongExponent(r), 1000.0f);
  cases.push_back(makeCase("Lambertian", LambertianBsdf{color}));
  // Reflection and transmission in proportions unlike their colours', and transmission alone.
  for (auto [name, reflectance, transmittance] : {std::tuple{"DiffuseTransmission", color, Vec3{0.3f, 0.5f, 0.2f}},
                                                  std::tuple{"DiffuseTransmissionOnly", Vec3{0, 0, 0}, color}}) {
    cases.push_back(makeCase(name, DiffuseTransmissionBsdf{reflectance, transmittance}));
    cases.back().refracts = false;
  }
  cases.push_back(makeCase("BlinnPhongSpecular", BlinnPhongSpecular{color, exponent}));
  cases.push_back(makeCase("BlinnPhong", BlinnPhongBsdf(color, {0.3f, 0.3f, 0.3f}, exponent)));
  cases.push_back(makeCase("GgxReflection", GgxReflection{GgxDistribution::isotropic(r), color}));
  cases.push_back(makeCase("GgxReflectionAnisotropic", GgxReflection{GgxDistribution::anisotropic(r, 0.8f), color}));
  cases.push_back(
      makeCase("RoughDielectricEntering", RoughDielectric{GgxDistribution::isotropic(r), 1.5f, color}, false));
  cases.push_back(
      makeCase("RoughDielectricLeaving", RoughDielectric{GgxDistribution::isotropic(r), 1.0f / 1.5f, color}, false));
  cases.push_back(makeCase("DisneyDiffuse", DisneyDiffuse{color, r, 0.5f, {0.3f, 0.3f, 0.3f}}));
  cases.push_back(makeCase("DisneyClearcoat", DisneyClearcoat{0.25f, lerp(1.0f - r, 0.1f, 0.001f)}));
  cases.push_back(makeCase("PbrDielectric", PbrBsdf(color, 0.0f, r, 0.5f)));
  cases.push_back(makeCase("PbrHalfMetal", PbrBsdf(color, 0.5f, r, 0.5f)));
  cases.push_back(makeCase("PbrMetal", PbrBsdf(color, 1.0f, r, 0.5f)));
  // KHR_materials_iridescence's film, strong (index 1.8) and of a thickness whose colours vary with the angle.
  cases.push_back(makeCase("PbrIridescent", PbrBsdf(color, 0.0f, r, 0.5f, 1.0f, 1.8f, 350.0f)));
  cases.push_back(makeCase("PbrIridescentHalfMetal", PbrBsdf(color, 0.5f, r, 0.5f, 0.7f, 1.3f, 500.0f)));
  cases.push_back(makeCase("Disney", DisneyBsdf(disneyMaterial(r), 1.5f)));
  Material iridescent = disneyMaterial(r);
  iridescent.metallic = 0.4f;
  iridescent.clearcoat = 0.5f;
  iridescent.iridescence = 1.0f;
  iridescent.iridescenceIor = 1.8f;
  iridescent.iridescenceThickness = 350.0f;
  cases.push_back(makeCase("DisneyIridescent", DisneyBsdf(iridescent, 1.5f)));
  Material all = disneyMaterial(r);
  all.metallic = 0.3f;
  all.anisotropic = 0.6f;
  all.subsurface = 0.5f;
  all.sheen = 0.8f;
  all.clearcoat = 1.0f;
  all.clearcoatGloss = 0.5f;
  all.specTrans = 0.4f;
  cases.push_back(makeCase("DisneyAllLobesEntering", DisneyBsdf(all, 1.5f), false));
  cases.push_back(makeCase("DisneyAllLobesLeaving", DisneyBsdf(all, 1.0f / 1.5f), false));
  Material glass = disneyMaterial(r);
  glass.specTrans = 1.0f;
  cases.push_back(makeCase("DisneyGlass", DisneyBsdf(glass, 1.5f), false));
  return cases;
}

}  // namespace candela::test
