// The media's sampling routines on their own: the Henyey-Greenstein phase function against its density
// (chi-square), and free-flight sampling's estimates of transmittance and of in-medium collisions against their
// closed forms (means over many runs).
#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "core/rng.h"
#include "kernel/media/distance_sampling.h"
#include "kernel/media/henyey_greenstein.h"
#include "support/chi2.h"

namespace candela::test {
namespace {

constexpr float kAsymmetries[] = {-0.7f, 0.0f, 0.3f, 0.9f};
constexpr int kChi2Tests = 5;  // the four asymmetries and the deliberately wrong density

Chi2Result phaseChi2(float sampledG, float densityG) {
  const Vec3 wo = normalize(Vec3{0.3f, -0.2f, 0.9f});
  Chi2Options options;
  options.testCount = kChi2Tests;
  return chi2TestSphere(
      [&](double u1, double u2, double) -> std::optional<Vec3> {
        const PhaseSample s = sampleHenyeyGreenstein(wo, sampledG, {float(u1), float(u2)});
        if (!(s.pdf > 0.0f)) return std::nullopt;
        return s.wi;
      },
      [&](Vec3 wi) { return double(henyeyGreensteinPdf(wo, wi, densityG)); }, options);
}

TEST(HenyeyGreenstein, SamplingMatchesItsDensity) {
  for (float g : kAsymmetries) {
    SCOPED_TRACE("g " + std::to_string(g));
    const Chi2Result r = phaseChi2(g, g);
    EXPECT_TRUE(r.passed) << r.message;
    EXPECT_NEAR(r.integral, 1.0, 2e-3);
  }
}

// The test must notice a density that is not the one sampled.
TEST(HenyeyGreenstein, Chi2RejectsAnotherAsymmetry) { EXPECT_FALSE(phaseChi2(0.3f, 0.4f).passed); }

// pbrt-v4's convention: wo points back along the incoming ray, so forward scattering (g > 0) prefers wi = -wo;
// the sample's density is the phase function's value.
TEST(HenyeyGreenstein, PositiveAsymmetryScattersForwards) {
  const Vec3 wo{0, 0, 1};
  EXPECT_GT(henyeyGreensteinPdf(wo, {0, 0, -1}, 0.5f), henyeyGreensteinPdf(wo, {0, 0, 1}, 0.5f));
  EXPECT_NEAR(henyeyGreensteinPdf(wo, {1, 0, 0}, 0.0f), 1.0 / (4.0 * kPi), 1e-7);
  const PhaseSample s = sampleHenyeyGreenstein(wo, 0.8f, {0.37f, 0.61f});
  EXPECT_NEAR(s.pdf, henyeyGreensteinPdf(wo, s.wi, 0.8f), 1e-4f * s.pdf);
}

// Free flight over a segment of length d in a medium of three different sigma_t, one channel sampling at a time:
// the weight of reaching the end averages to exp(-sigma_t d) per channel (the transmittance), and the weight of
// colliding inside, over sigma_s, to the integral of the transmittance over the segment,
// (1 - exp(-sigma_t d)) / sigma_t. Each mean is tested to within 5 standard errors.
struct FlightMeans {
  Vec3 reach, collide, reachError, collideError;
};

FlightMeans flightMeans(const Medium& m, float d, uint32_t runs) {
  double sum[2][3] = {}, sumSquares[2][3] = {};
  for (uint32_t i = 0; i < runs; ++i) {
    const Uint4 bits = pcg4d({i, 17u, 3u, 0x9e3779b9u});
    const MediumStep step = sampleMediumDistance(m, d, bitsToUnitFloat(bits.x), bitsToUnitFloat(bits.y));
    auto over = [](float w, float s) { return s > 0.0f ? w / s : 0.0f; };
    const Vec3 perSigmaS = step.scattered ? Vec3{over(step.weight.x, m.sigmaS.x), over(step.weight.y, m.sigmaS.y),
                                                 over(step.weight.z, m.sigmaS.z)}
                                          : Vec3{};
    const Vec3 reach = step.scattered ? Vec3{} : step.weight;
    const float values[2][3] = {{reach.x, reach.y, reach.z}, {perSigmaS.x, perSigmaS.y, perSigmaS.z}};
    for (int k = 0; k < 2; ++k)
      for (int c = 0; c < 3; ++c) {
        sum[k][c] += values[k][c];
        sumSquares[k][c] += double(values[k][c]) * values[k][c];
      }
  }
  auto mean = [&](int k, int c) { return float(sum[k][c] / runs); };
  auto error = [&](int k, int c) {
    const double mu = sum[k][c] / runs;
    return float(std::sqrt(std::max(0.0, sumSquares[k][c] / runs - mu * mu) / runs));
  };
  return {{mean(0, 0), mean(0, 1), mean(0, 2)},
          {mean(1, 0), mean(1, 1), mean(1, 2)},
          {error(0, 0), error(0, 1), error(0, 2)},
          {error(1, 0), error(1, 1), error(1, 2)}};
}

void expectWithin(Vec3 mean, Vec3 error, Vec3 expected, float z) {
  EXPECT_NEAR(mean.x, expected.x, z * error.x + 1e-6f);
  EXPECT_NEAR(mean.y, expected.y, z * error.y + 1e-6f);
  EXPECT_NEAR(mean.z, expected.z, z * error.z + 1e-6f);
}

TEST(MediumDistanceSampling, EstimatesAreUnbiasedPerChannel) {
  Medium m;
  m.sigmaA = {0.1f, 0.5f, 2.0f};
  m.sigmaS = {0.4f, 1.0f, 0.5f};
  const float d = 1.3f;
  const FlightMeans f = flightMeans(m, d, 400'000);
  const Vec3 st = mediumSigmaT(m);
  const Vec3 transmittance = mediumTransmittance(m, d);
  expectWithin(f.reach, f.reachError, transmittance, 5.0f);
  expectWithin(f.collide, f.collideError,
               {(1.0f - transmittance.x) / st.x, (1.0f - transmittance.y) / st.y, (1.0f - transmittance.z) / st.z},
               5.0f);
  // The test resolves an error of 2%: a transmittance off by that much is rejected.
  EXPECT_GT(std::fabs(f.reach.z - 1.02f * transmittance.z), 5.0f * f.reachError.z);
}

// A channel that does not interact never stops the ray: its transmittance estimate is 1 with every sample that
// reaches the end, while the others keep theirs.
TEST(MediumDistanceSampling, AChannelWithoutInteractionIsNeverStopped) {
  Medium m;
  m.sigmaA = {0.0f, 1.0f, 0.0f};
  m.sigmaS = {0.0f, 0.0f, 3.0f};
  const FlightMeans f = flightMeans(m, 0.7f, 200'000);
  expectWithin(f.reach, f.reachError, mediumTransmittance(m, 0.7f), 5.0f);
  EXPECT_EQ(mediumTransmittance(m, kInf).x, 1.0f);
  EXPECT_EQ(mediumTransmittance(m, kInf).y, 0.0f);
}

}  // namespace
}  // namespace candela::test
