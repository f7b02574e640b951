#include <gtest/gtest.h>

#include "core/sampling.h"
#include "support/chi2.h"

namespace candela {
namespace {

using test::Chi2Options;
using test::chi2TestSphere;
using test::chi2TestSquare;

constexpr int kChi2Tests = 3;

TEST(Sampling, CosineHemisphereMatchesItsPdf) {
  Chi2Options options;
  options.testCount = kChi2Tests;
  auto r = chi2TestSphere(
      [](double u1, double u2, double) -> std::optional<Vec3> {
        return sampleCosineHemisphere({float(u1), float(u2)});
      },
      [](Vec3 d) { return double(cosineHemispherePdf(d.z)); }, options);
  EXPECT_TRUE(r.passed) << r.message;
  EXPECT_NEAR(r.integral, 1.0, 1e-3);
}

TEST(Sampling, UniformSphereMatchesItsPdf) {
  Chi2Options options;
  options.testCount = kChi2Tests;
  auto r = chi2TestSphere(
      [](double u1, double u2, double) -> std::optional<Vec3> {
        return sampleUniformSphere({float(u1), float(u2)});
      },
      [](Vec3) { return double(uniformSpherePdf()); }, options);
  EXPECT_TRUE(r.passed) << r.message;
  EXPECT_NEAR(r.integral, 1.0, 1e-3);
}

// Barycentrics (b0, b1) of a uniform point on a triangle fill the lower-left half of the unit square
// uniformly, with density 2 there.
TEST(Sampling, UniformTriangleIsUniform) {
  Chi2Options options;
  options.binsX = options.binsY = 50;
  options.testCount = kChi2Tests;
  auto r = chi2TestSquare(
      [](double u1, double u2, double) -> std::optional<Vec2> {
        return sampleUniformTriangle({float(u1), float(u2)});
      },
      [](double x, double y) { return x + y <= 1.0 ? 2.0 : 0.0; }, options);
  EXPECT_TRUE(r.passed) << r.message;
}

// A sampler that is wrong by a little must fail: the test has power.
TEST(Sampling, Chi2RejectsASlightlyWrongPdf) {
  Chi2Options options;
  auto r = chi2TestSphere(
      [](double u1, double u2, double) -> std::optional<Vec3> {
        return sampleCosineHemisphere({float(u1), float(u2)});
      },
      [](Vec3 d) { return d.z > 0 ? double(0.9f * cosineHemispherePdf(d.z) + 0.1f / (2.0f * kPi)) : 0.0; }, options);
  EXPECT_FALSE(r.passed) << r.message;
}

TEST(Sampling, PowerHeuristic) {
  EXPECT_FLOAT_EQ(powerHeuristic(1.0f, 1.0f), 0.5f);
  EXPECT_FLOAT_EQ(powerHeuristic(3.0f, 1.0f), 0.9f);
  EXPECT_FLOAT_EQ(powerHeuristic(2.0f, 5.0f) + powerHeuristic(5.0f, 2.0f), 1.0f);
  EXPECT_FLOAT_EQ(powerHeuristic(kInf, 1.0f), 1.0f);
  EXPECT_FLOAT_EQ(powerHeuristic(0.0f, 0.0f), 0.0f);
}

TEST(Sampling, FindIntervalLocatesTheBucket) {
  const float cdf[] = {0.0f, 0.25f, 0.5f, 1.0f};
  EXPECT_EQ(findInterval(cdf, 3, 0.0f), 0);
  EXPECT_EQ(findInterval(cdf, 3, 0.24f), 0);
  EXPECT_EQ(findInterval(cdf, 3, 0.25f), 1);
  EXPECT_EQ(findInterval(cdf, 3, 0.99f), 2);
}

}  // namespace
}  // namespace candela
