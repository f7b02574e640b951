#include <gtest/gtest.h>

#include "core/rng.h"
#include "kernel/bsdf/bsdf.h"
#include "support/chi2.h"

namespace candela {
namespace {

constexpr float kIncidentAngles[] = {0.0f, 45.0f, 80.0f, 89.0f};
constexpr int kChi2Tests = 4;

Vec3 directionAt(float thetaDegrees) {
  float t = thetaDegrees * kPi / 180.0f;
  return {sinf(t), 0.0f, cosf(t)};
}

Bsdf whiteLambertian(Vec3 normal) {
  Material m;
  m.baseColor = {1, 1, 1};
  SurfaceInteraction si;
  si.geometricNormal = si.shadingNormal = normal;
  return Bsdf(m, si, normal);
}

class LambertianAtAngle : public ::testing::TestWithParam<float> {};

TEST_P(LambertianAtAngle, SamplesMatchThePdf) {
  Vec3 n = normalize(Vec3{0.3f, -0.2f, 0.9f});
  Bsdf bsdf = whiteLambertian(n);
  Frame frame = Frame::fromNormal(n);
  Vec3 wo = frame.toWorld(directionAt(GetParam()));
  test::Chi2Options options;
  options.testCount = kChi2Tests;
  // Bins are laid out in the shading frame so that the hemisphere boundary falls on a bin edge.
  test::Chi2Result r = test::chi2TestSphere(
      [&](double u1, double u2, double) -> std::optional<Vec3> {
        BsdfSample s = bsdf.sample(wo, 0.5f, {float(u1), float(u2)});
        if (!s.valid) return std::nullopt;
        return frame.toLocal(s.wi);
      },
      [&](Vec3 local) { return double(bsdf.pdf(wo, frame.toWorld(local))); }, options);
  EXPECT_TRUE(r.passed) << r.message;
  EXPECT_NEAR(r.integral, 1.0, 1e-3);
}

TEST_P(LambertianAtAngle, SampleAgreesWithEvalAndPdf) {
  Vec3 n{0, 0, 1};
  Bsdf bsdf = whiteLambertian(n);
  Vec3 wo = directionAt(GetParam());
  for (uint32_t i = 0; i < 1000; ++i) {
    BsdfSample s = bsdf.sample(wo, 0.5f, {randomUniform(i, 0, 0, 1), randomUniform(i, 0, 1, 1)});
    ASSERT_TRUE(s.valid);
    EXPECT_NEAR(s.pdf, bsdf.pdf(wo, s.wi), 1e-5f);
    Vec3 f = bsdf.eval(wo, s.wi);
    EXPECT_NEAR(s.f.x, f.x, 1e-6f);
  }
}

// The directional albedo of a white Lambertian is exactly 1; f cos / pdf is 1 for every sample, so the
// estimate has no noise and the bound is float rounding.
TEST_P(LambertianAtAngle, WhiteAlbedoIsOne) {
  Bsdf bsdf = whiteLambertian({0, 0, 1});
  Vec3 wo = directionAt(GetParam());
  double sum = 0.0;
  const int n = 10000;
  for (uint32_t i = 0; i < n; ++i) {
    BsdfSample s = bsdf.sample(wo, 0.5f, {randomUniform(i, 0, 0, 2), randomUniform(i, 0, 1, 2)});
    if (s.valid) sum += double(s.f.x) * s.wi.z / s.pdf;
  }
  EXPECT_NEAR(sum / n, 1.0, 1e-4);
}

TEST(Lambertian, IsReciprocal) {
  Bsdf bsdf = whiteLambertian({0, 0, 1});
  Vec3 a = normalize(Vec3{0.2f, 0.1f, 0.9f}), b = normalize(Vec3{-0.5f, 0.3f, 0.4f});
  EXPECT_FLOAT_EQ(bsdf.eval(a, b).x, bsdf.eval(b, a).x);
}

TEST(Lambertian, ReflectsNothingThroughTheSurface) {
  Bsdf bsdf = whiteLambertian({0, 0, 1});
  EXPECT_TRUE(isBlack(bsdf.eval({0, 0, 1}, {0, 0.6f, -0.8f})));
  EXPECT_EQ(bsdf.pdf({0, 0, 1}, {0, 0.6f, -0.8f}), 0.0f);
}

INSTANTIATE_TEST_SUITE_P(IncidentAngles, LambertianAtAngle, ::testing::ValuesIn(kIncidentAngles));

}  // namespace
}  // namespace candela
