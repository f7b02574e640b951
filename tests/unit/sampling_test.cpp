#include <gtest/gtest.h>

#include "core/sampling.h"
#include "core/spherical_triangle.h"
#include "support/chi2.h"

namespace candela {
namespace {

using test::Chi2Options;
using test::Chi2Result;
using test::chi2TestSphere;
using test::chi2TestSquare;

constexpr int kChi2Tests = 5;

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

// Whether the ray from p along d meets the triangle (Moller-Trumbore), for the spherical triangle's density.
bool rayMeetsTriangle(Vec3 p, Vec3 d, Vec3 p0, Vec3 p1, Vec3 p2) {
  Vec3 e1 = p1 - p0, e2 = p2 - p0, s1 = cross(d, e2);
  float divisor = dot(s1, e1);
  if (divisor == 0.0f) return false;
  Vec3 toP = p - p0;
  float b1 = dot(toP, s1) / divisor, b2 = dot(d, cross(toP, e1)) / divisor, t = dot(e2, cross(toP, e1)) / divisor;
  return b1 >= 0.0f && b2 >= 0.0f && b1 + b2 <= 1.0f && t > 0.0f;
}

struct TriangleSeenFrom {
  Vec3 p0, p1, p2, p;
};

// A triangle filling much of the view (about 1.6 sr) and a small, slanted one (about 0.05 sr).
constexpr TriangleSeenFrom kSphericalTriangles[] = {
    {{-1, -1, 1}, {1.5f, -0.5f, 0.8f}, {0, 1, 1.2f}, {0, 0, 0}},
    {{2, 1, 3}, {2.5f, 1.2f, 2.0f}, {1.8f, 1.9f, 2.6f}, {0.1f, 0.2f, 0}}};

Chi2Result chi2TestSphericalTriangle(const TriangleSeenFrom& t, bool byArea, const Chi2Options& options) {
  Vec3 a = normalize(t.p0 - t.p), b = normalize(t.p1 - t.p), c = normalize(t.p2 - t.p);
  double solidAngle = sphericalTriangleArea(a, b, c);
  return chi2TestSphere(
      [&](double u1, double u2, double) -> std::optional<Vec3> {
        Vec2 bary = byArea ? sampleUniformTriangle({float(u1), float(u2)})
                           : sampleSphericalTriangle(t.p0, t.p1, t.p2, t.p, {float(u1), float(u2)}).barycentrics;
        return normalize(t.p0 + (t.p1 - t.p0) * bary.x + (t.p2 - t.p0) * bary.y - t.p);
      },
      [&](Vec3 d) { return rayMeetsTriangle(t.p, d, t.p0, t.p1, t.p2) ? 1.0 / solidAngle : 0.0; }, options);
}

TEST(Sampling, SphericalTriangleIsUniformOverItsSolidAngle) {
  for (const TriangleSeenFrom& t : kSphericalTriangles) {
    Chi2Options options;
    options.binsX = 80;
    options.binsY = 160;
    options.testCount = kChi2Tests;
    Chi2Result r = chi2TestSphericalTriangle(t, /*byArea=*/false, options);
    EXPECT_TRUE(r.passed) << r.message;
    EXPECT_NEAR(r.integral, 1.0, 1e-2);
    // The returned density is that of the solid angle, accurate for small triangles too.
    Vec3 a = normalize(t.p0 - t.p), b = normalize(t.p1 - t.p), c = normalize(t.p2 - t.p);
    SphericalTriangleSample s = sampleSphericalTriangle(t.p0, t.p1, t.p2, t.p, {0.3f, 0.6f});
    EXPECT_FLOAT_EQ(s.pdf, 1.0f / sphericalTriangleArea(a, b, c));
  }
}

// Points uniform by area give directions that are not uniform by solid angle: the test must see it.
TEST(Sampling, Chi2RejectsAreaSamplingAsUniformSolidAngle) {
  Chi2Options options;
  options.binsX = 80;
  options.binsY = 160;
  EXPECT_FALSE(chi2TestSphericalTriangle(kSphericalTriangles[0], /*byArea=*/true, options).passed);
}

TEST(Sampling, SphericalTriangleAreaOfAnOctantIsAnEighthOfTheSphere) {
  EXPECT_NEAR(sphericalTriangleArea({1, 0, 0}, {0, 1, 0}, {0, 0, 1}), kPi / 2.0f, 1e-6f);
  EXPECT_NEAR(sphericalTriangleArea({0, 0, 1}, {0, 1, 0}, {1, 0, 0}), kPi / 2.0f, 1e-6f);
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
