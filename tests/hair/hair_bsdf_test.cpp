// The hair model (kernel/bsdf/hair.h) as pbrt-v4's HairBxDF tests check it: a fibre that absorbs nothing scatters
// all the light it meets (the white furnace), its samples carry the weight 1 there, their directions follow the
// density (chi-square) and the density integrates to 1.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <vector>

#include "core/rng.h"
#include "core/sampling.h"
#include "kernel/bsdf/hair.h"
#include "support/chi2.h"

namespace candela::test {
namespace {

constexpr float kRoughnesses[] = {0.1f, 0.3f, 0.5f, 0.7f, 0.9f};
constexpr float kOffsets[] = {-0.9f, -0.4f, 0.0f, 0.5f, 0.95f};

HairBsdf whiteHair(float h, float betaM, float betaN, float alphaDegrees) {
  return HairBsdf(h, 1.55f, {0, 0, 0}, betaM, betaN, alphaDegrees);
}

Vec3 randomDirection(uint32_t i, uint32_t seed) {
  return sampleUniformSphere({randomUniform(i, 0, 0, seed), randomUniform(i, 0, 1, seed)});
}

// The integrals over every incident direction of the fibre's scattering function (f times the cosine to the
// normal that eval() divides by) and of the density, by midpoint quadrature in the fibre's own coordinates (sin
// theta along the fibre, phi around it: the solid angle is d(sin theta) d(phi)), on a grid fine enough for the
// narrowest lobes tested (roughness 0.1: about 0.05 radians wide). Independent of every sampling routine.
struct SphereIntegrals {
  double scattered = 0.0;  // luminance
  double density = 0.0;
};

SphereIntegrals integrate(const HairBsdf& hair, Vec3 wo) {
  constexpr int kThetaCells = 400, kPhiCells = 800;
  SphereIntegrals sum;
  for (int i = 0; i < kThetaCells; ++i) {
    const double sinTheta = -1.0 + 2.0 * (i + 0.5) / kThetaCells, cosTheta = std::sqrt(1.0 - sinTheta * sinTheta);
    for (int j = 0; j < kPhiCells; ++j) {
      const double phi = 2.0 * kPi * (j + 0.5) / kPhiCells;
      const Vec3 wi{float(sinTheta), float(cosTheta * std::cos(phi)), float(cosTheta * std::sin(phi))};
      const BsdfEval e = hair.evalPdf(wo, wi);
      sum.scattered += luminance(e.f) * std::fabs(wi.z);
      sum.density += e.pdf;
    }
  }
  const double cell = (2.0 / kThetaCells) * (2.0 * kPi / kPhiCells);
  return {sum.scattered * cell, sum.density * cell};
}

// pbrt-v4's WhiteFurnace, at fixed offsets rather than averaged over them, with the scales' tilt and without:
// what a fibre that absorbs nothing scatters adds up to 1, and so does the density. Within 0.5%: Mp's form for
// narrow lobes takes I0 as ten terms of its series, as pbrt-v4's does (about 0.998 at beta_m 0.3).
TEST(Hair, WhiteFurnaceScattersEverythingAndPdfIntegratesToOne) {
  uint32_t k = 0;
  for (float betaM : {0.1f, 0.3f, 0.6f, 0.9f})
    for (float betaN : {0.1f, 0.3f, 0.6f, 0.9f})
      for (float alpha : {0.0f, 2.0f}) {
        const float h = kOffsets[k % std::size(kOffsets)];
        const Vec3 wo = randomDirection(k++, 3);
        const SphereIntegrals integrals = integrate(whiteHair(h, betaM, betaN, alpha), wo);
        EXPECT_NEAR(integrals.scattered, 1.0, 5e-3)
            << "beta_m " << betaM << " beta_n " << betaN << " alpha " << alpha << " h " << h;
        EXPECT_NEAR(integrals.density, 1.0, 5e-3)
            << "beta_m " << betaM << " beta_n " << betaN << " alpha " << alpha << " h " << h;
      }
}

// Absorption only takes light away, the more the darker.
TEST(Hair, AbsorbingHairScattersLess) {
  const Vec3 wo = normalize(Vec3{0.3f, 0.5f, 0.8f});
  double previous = 1.01;
  for (float sigmaA : {0.0f, 0.2f, 1.0f, 5.0f}) {
    const double albedo = integrate(HairBsdf(0.2f, 1.55f, {sigmaA, sigmaA, sigmaA}, 0.3f, 0.3f, 2.0f), wo).scattered;
    EXPECT_LT(albedo, previous) << sigmaA;
    previous = albedo;
  }
  EXPECT_GT(previous, 0.02) << "the surface reflection (p = 0) remains";
}

// pbrt-v4's SamplingWeights and WhiteFurnaceSampled: where the fibre absorbs nothing, the terms' attenuations
// are grey and sum to 1, so that picking a term by its attenuation and sampling its lobes exactly is the whole
// f |cos|: every sample's weight f |cos| / pdf is 1.
TEST(Hair, SampleWeightsAreOneWithoutAbsorption) {
  for (float betaM : kRoughnesses)
    for (float betaN : kRoughnesses)
      for (float alpha : {0.0f, 2.0f})
        for (uint32_t i = 0; i < 2000; ++i) {
          const float h = std::clamp(-1.0f + 2.0f * randomUniform(i, 1, 0, 5), -0.999999f, 0.999999f);
          const HairBsdf hair = whiteHair(h, betaM, betaN, alpha);
          const Vec3 wo = randomDirection(i, 7);
          const BsdfSample s =
              hair.sample(wo, randomUniform(i, 1, 1, 5), {randomUniform(i, 1, 2, 5), randomUniform(i, 1, 3, 5)});
          ASSERT_TRUE(s.valid) << i;
          ASSERT_FALSE(s.isDelta);
          ASSERT_EQ(s.eta, 1.0f);
          const float weight = luminance(s.f) * std::fabs(s.wi.z) / s.pdf;
          ASSERT_NEAR(weight, 1.0f, 1e-3f)
              << "beta_m " << betaM << " beta_n " << betaN << " alpha " << alpha << " h " << h << " sample " << i;
        }
}

// A sample's f and density are eval()'s and pdf()'s at its direction, for hair that absorbs, in colour.
TEST(Hair, SampleReturnsEvalAndPdf) {
  for (float betaM : kRoughnesses)
    for (float betaN : kRoughnesses)
      for (uint32_t i = 0; i < 500; ++i) {
        const HairBsdf hair(-1.0f + 2.0f * randomUniform(i, 2, 0, 9), 1.55f, {0.2f, 0.6f, 1.5f}, betaM, betaN, 2.0f);
        const Vec3 wo = randomDirection(i, 11);
        const BsdfSample s =
            hair.sample(wo, randomUniform(i, 2, 1, 9), {randomUniform(i, 2, 2, 9), randomUniform(i, 2, 3, 9)});
        if (!s.valid) continue;
        const BsdfEval e = hair.evalPdf(wo, s.wi);
        ASSERT_NEAR(s.pdf, e.pdf, 2e-3f * e.pdf) << i;
        for (int c = 0; c < 3; ++c) ASSERT_NEAR(s.f[c], e.f[c], 2e-3f * e.f[c] + 1e-7f) << i;
        ASSERT_EQ(hair.pdf(wo, s.wi), e.pdf);
        ASSERT_EQ(hair.eval(wo, s.wi).y, e.f.y);
      }
}

struct Chi2Case {
  float betaM, betaN, h;
  Vec3 wo;
};

std::vector<Chi2Case> chi2Cases() {
  std::vector<Chi2Case> cases;
  // Across the fibre, and nearly along it.
  const Vec3 directions[] = {normalize(Vec3{0.2f, 0.4f, 0.9f}), normalize(Vec3{-0.9f, 0.1f, 0.3f})};
  const float roughnesses[][2] = {{0.3f, 0.3f}, {0.2f, 0.7f}, {0.8f, 0.25f}, {1.0f, 1.0f}};
  uint32_t k = 0;
  for (const auto& beta : roughnesses)
    for (Vec3 wo : directions) cases.push_back({beta[0], beta[1], kOffsets[k++ % std::size(kOffsets)], wo});
  return cases;
}

Chi2Result runChi2(const HairBsdf& hair, Vec3 wo, int testCount) {
  Chi2Options o;
  o.sampleCount = 200'000;
  o.binsX = 20;
  o.binsY = 40;
  o.testCount = testCount;
  return chi2TestSphere(
      [&](double u1, double u2, double u3) -> std::optional<Vec3> {
        const BsdfSample s = hair.sample(wo, float(u3), {float(u1), float(u2)});
        if (!s.valid) return std::nullopt;
        return s.wi;
      },
      [&](Vec3 wi) { return double(hair.pdf(wo, wi)); }, o);
}

// The directions sample() draws follow pdf(), for coloured absorption (the terms are then picked by their mean
// attenuation, not by the whole of f) and the scales' tilt.
TEST(Hair, SamplesFollowPdf) {
  const std::vector<Chi2Case> cases = chi2Cases();
  for (const Chi2Case& c : cases) {
    const HairBsdf hair(c.h, 1.55f, {0.25f, 0.5f, 1.0f}, c.betaM, c.betaN, 2.0f);
    const Chi2Result r = runChi2(hair, c.wo, int(cases.size()));
    EXPECT_TRUE(r.passed) << "beta_m " << c.betaM << " beta_n " << c.betaN << " h " << c.h << ": " << r.message;
  }
}

}  // namespace
}  // namespace candela::test
