// Directional albedo: Monte Carlo estimates through sample(), checked against bounds, analytic values and an
// independent quadrature of eval().
#include <gtest/gtest.h>

#include "bsdf/bsdf_cases.h"
#include "core/rng.h"

namespace candela::test {
namespace {

struct Estimate {
  double mean = 0.0, standardError = 0.0;
};

// Mean of f |cos| / pdf over sample() draws (luminance), with transmitted samples multiplied by eta^2 to undo
// the radiance compression: the estimate is then the fraction of energy scattered.
Estimate albedo(const BsdfCase& c, Vec3 wo, int samples, uint32_t seed = 11) {
  double sum = 0.0, sum2 = 0.0;
  for (int i = 0; i < samples; ++i) {
    uint32_t k = uint32_t(i);
    BsdfSample s =
        c.sample(wo, randomUniform(k, 0, 0, seed), {randomUniform(k, 0, 1, seed), randomUniform(k, 0, 2, seed)});
    double w = 0.0;
    if (s.valid) w = double(luminance(s.f)) * std::fabs(s.wi.z) / s.pdf * (s.wi.z < 0 ? s.eta * s.eta : 1.0f);
    sum += w;
    sum2 += w * w;
  }
  double mean = sum / samples;
  return {mean, std::sqrt(std::max(0.0, sum2 / samples - mean * mean) / samples)};
}

constexpr float kAngles[] = {0.0f, 45.0f, 75.0f, 89.0f};

TEST(BsdfEnergy, WhiteLambertianReflectsEverything) {
  BsdfCase c = makeCase("white", LambertianBsdf{{1, 1, 1}});
  for (float a : kAngles) {
    Estimate e = albedo(c, directionAt(a), 10'000);
    EXPECT_NEAR(e.mean, 1.0, 1e-6);  // every sample weighs exactly 1
  }
}

TEST(BsdfEnergy, SmoothDielectricReflectsPlusTransmitsEverything) {
  for (float eta : {1.5f, 1.0f / 1.5f, 2.4f})
    for (float a : kAngles) {
      Estimate e = albedo(makeCase("glass", SmoothDielectricBsdf{eta, {1, 1, 1}}), directionAt(a), 10'000);
      EXPECT_NEAR(e.mean, 1.0, 1e-5) << "eta " << eta << " at " << a;
    }
}

// Grey reflectance and transmittance: every sample weighs their sum, to either side.
TEST(BsdfEnergy, DiffuseTransmissionScattersReflectancePlusTransmittance) {
  BsdfCase c = makeCase("grey", DiffuseTransmissionBsdf{{0.6f, 0.6f, 0.6f}, {0.3f, 0.3f, 0.3f}});
  for (float a : kAngles) {
    Estimate e = albedo(c, directionAt(a), 10'000);
    EXPECT_NEAR(e.mean, 0.9, 1e-5) << a;
  }
}

// No model but Disney reflects more than arrives, over roughness, angle and parameter sweeps (white base colour:
// the hardest case). Tolerance: 4 standard errors of the estimate.
TEST(BsdfEnergy, AlbedoAtMostOne) {
  for (float r : {0.05f, 0.3f, 0.6f, 1.0f}) {
    Vec3 white{1, 1, 1};
    float n = roughnessToPhongExponent(r);
    std::vector<BsdfCase> cases = {
        makeCase("BlinnPhong", BlinnPhongBsdf(white, white * 0.3f, n)),
        makeCase("BlinnPhongAllSpecular", BlinnPhongBsdf(white, white, n)),
        makeCase("GgxWhite", GgxReflection{GgxDistribution::isotropic(r), white}),
        makeCase("GgxAnisotropic", GgxReflection{GgxDistribution::anisotropic(r, 1.0f), white}),
        makeCase("PbrDielectric", PbrBsdf(white, 0.0f, r, 1.0f)),
        makeCase("PbrMetal", PbrBsdf(white, 1.0f, r, 0.5f)),
        makeCase("PbrHalfMetal", PbrBsdf(white, 0.5f, r, 0.5f)),
        makeCase("PbrIridescent", PbrBsdf(white, 0.0f, r, 1.0f, 1.0f, 2.0f, 250.0f)),
        makeCase("PbrIridescentThick", PbrBsdf(white, 0.0f, r, 1.0f, 1.0f, 1.8f, 800.0f)),
        makeCase("PbrIridescentMetal", PbrBsdf(white, 1.0f, r, 0.5f, 1.0f, 1.8f, 245.0f)),
        makeCase("RoughDielectricIn", RoughDielectric{GgxDistribution::isotropic(r), 1.5f, white}),
        makeCase("RoughDielectricOut", RoughDielectric{GgxDistribution::isotropic(r), 1 / 1.5f, white}),
        makeCase("Clearcoat", DisneyClearcoat{0.25f, lerp(1 - r, 0.1f, 0.001f)}),
    };
    Material metal = disneyMaterial(r), glass = disneyMaterial(r);
    metal.baseColor = glass.baseColor = white;
    metal.metallic = 1.0f;
    metal.anisotropic = 0.5f;
    glass.specTrans = 1.0f;
    cases.push_back(makeCase("DisneyMetal", DisneyBsdf(metal, 1.5f)));
    cases.push_back(makeCase("DisneyGlassIn", DisneyBsdf(glass, 1.5f)));
    cases.push_back(makeCase("DisneyGlassOut", DisneyBsdf(glass, 1 / 1.5f)));
    for (const BsdfCase& c : cases)
      for (float a : kAngles) {
        Estimate e = albedo(c, directionAt(a, 20.0f), 20'000);
        EXPECT_LE(e.mean, 1.0 + 4 * e.standardError + 1e-6) << c.name << " r=" << r << " at " << a << " degrees";
      }
  }
}

// Burley's diffuse is deliberately not energy conserving. Along the normal its albedo for a white base is, in
// closed form, 1 + 2 integral mu (fd90(mu) - 1)(1 - mu)^5 dmu with fd90 = 0.5 + roughness (1 + mu):
// 1 - 1/42 at roughness 0, 1 + 1/168 at 0.5 and 1 + 1/28 at 1. That pins the implementation, and shows why
// the Disney model is exempt from the bound above (with the specular lobe on top it reaches ~1.6 at grazing).
TEST(BsdfEnergy, DisneyDiffuseMatchesItsClosedForm) {
  struct Known {
    float roughness;
    double albedo;
  };
  for (Known k : {Known{0.0f, 1.0 - 1.0 / 42}, Known{0.5f, 1.0 + 1.0 / 168}, Known{1.0f, 1.0 + 1.0 / 28}}) {
    BsdfCase c = makeCase("DisneyDiffuse", DisneyDiffuse{{1, 1, 1}, k.roughness, 0.0f, {0, 0, 0}});
    Estimate e = albedo(c, {0, 0, 1}, 200'000);
    EXPECT_NEAR(e.mean, k.albedo, 4 * e.standardError) << "roughness " << k.roughness;
    EXPECT_NEAR(albedoByQuadrature(c, {0, 0, 1}), k.albedo, 1e-4);
  }
}

// The lobe-choice mixtures are unbiased: their Monte Carlo albedo equals the quadrature of eval(), which never
// samples. Tolerance: 4 standard errors plus the quadrature's own error (below 1e-3 on these smooth lobes,
// from halving the grid).
TEST(BsdfEnergy, MixtureSamplingIsUnbiased) {
  for (float r : {0.3f, 0.6f, 1.0f})
    for (const BsdfCase& c : casesAtRoughness(r))
      for (float a : {20.0f, 70.0f}) {
        Vec3 wo = directionAt(a, 40.0f);
        Estimate e = albedo(c, wo, 100'000);
        double reference = albedoByQuadrature(c, wo);
        if (c.name.find("Dielectric") != std::string::npos || c.name.find("Glass") != std::string::npos ||
            c.name.find("AllLobes") != std::string::npos || c.name.find("Transmission") != std::string::npos) {
          // The quadrature covers reflection only; compare the reflected part of the estimate instead.
          double sum = 0;
          for (int i = 0; i < 100'000; ++i) {
            uint32_t k = uint32_t(i);
            BsdfSample s =
                c.sample(wo, randomUniform(k, 0, 0, 11), {randomUniform(k, 0, 1, 11), randomUniform(k, 0, 2, 11)});
            if (s.valid && s.wi.z > 0) sum += luminance(s.f) * s.wi.z / s.pdf;
          }
          e.mean = sum / 100'000;
        }
        EXPECT_NEAR(e.mean, reference, 4 * e.standardError + 2e-3) << c.name << " r=" << r << " at " << a;
      }
}

}  // namespace
}  // namespace candela::test
