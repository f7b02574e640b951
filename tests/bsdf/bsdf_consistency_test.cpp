// sample() agrees with eval() and pdf(); densities integrate to the probability that sampling succeeds;
// reflection models are reciprocal; the delta lobes reflect and refract where optics says.
#include <gtest/gtest.h>

#include "bsdf/bsdf_cases.h"
#include "core/rng.h"
#include "support/chi2.h"

namespace candela::test {
namespace {

constexpr float kRoughnesses[] = {0.05f, 0.3f, 1.0f};

float relativeDifference(float a, float b) {
  return std::fabs(a - b) / std::fmax(std::fmax(std::fabs(a), std::fabs(b)), 1e-6f);
}

TEST(BsdfConsistency, SampleReturnsEvalAndPdf) {
  for (float r : kRoughnesses)
    for (const BsdfCase& c : casesAtRoughness(r))
      for (uint32_t i = 0; i < 2000; ++i) {
        float u[5];
        for (uint32_t k = 0; k < 5; ++k) u[k] = randomUniform(i, 0, k, 7);
        Vec3 wo = sampleCosineHemisphere({u[0], u[1]});
        if (wo.z < 1e-3f) continue;
        BsdfSample s = c.sample(wo, u[2], {u[3], u[4]});
        if (!s.valid) continue;
        float pdf = c.pdf(wo, s.wi);
        Vec3 f = c.eval(wo, s.wi);
        // float round-off: sample() builds its half vector from u, eval() from wo + wi.
        ASSERT_LT(relativeDifference(s.pdf, pdf), 2e-3f) << c.name << " r=" << r;
        ASSERT_LT(relativeDifference(luminance(s.f), luminance(f)), 2e-3f) << c.name << " r=" << r;
        ASSERT_FALSE(s.isDelta);
        ASSERT_EQ(s.eta != 1.0f, s.wi.z < 0.0f) << c.name << ": eta belongs to transmitted samples only";
      }
}

// The density integrated over the sphere equals the fraction of sample() calls that succeed: 1 for lobes that
// always produce a direction (diffuse, dielectric), less for reflection lobes whose microfacet sample can point
// below the horizon. Integration by the chi-square support's adaptive quadrature; the success rate's binomial
// standard deviation sets the tolerance (5 sigma plus 2e-3 for the quadrature).
TEST(BsdfConsistency, PdfIntegratesToTheSuccessRate) {
  for (float r : {0.3f, 1.0f})
    for (const BsdfCase& c : casesAtRoughness(r)) {
      Vec3 wo = directionAt(50.0f, 20.0f);
      constexpr int kSamples = 100'000;
      int successes = 0;
      for (uint32_t i = 0; i < kSamples; ++i)
        successes +=
            c.sample(wo, randomUniform(i, 1, 0, 3), {randomUniform(i, 1, 1, 3), randomUniform(i, 1, 2, 3)}).valid;
      double rate = double(successes) / kSamples;
      double sigma = std::sqrt(std::max(rate * (1 - rate), 1e-12) / kSamples);
      Chi2Options o;
      o.sampleCount = 1;
      Chi2Result integral = chi2TestSphere([](double, double, double) { return std::optional<Vec3>(); },
                                           [&](Vec3 wi) { return double(c.pdf(wo, wi)); }, o);
      EXPECT_NEAR(integral.integral, rate, 5 * sigma + 2e-3) << c.name << " r=" << r;
      EXPECT_LE(integral.integral, 1.0 + 2e-3) << c.name;
    }
}

TEST(BsdfConsistency, NeverFailingLobesIntegrateToOne) {
  Vec3 wo = directionAt(70.0f);
  Chi2Options o;
  o.sampleCount = 1;
  auto integral = [&](const BsdfCase& c) {
    return chi2TestSphere([](double, double, double) { return std::optional<Vec3>(); },
                          [&](Vec3 wi) { return double(c.pdf(wo, wi)); }, o)
        .integral;
  };
  EXPECT_NEAR(integral(makeCase("Lambertian", LambertianBsdf{{1, 1, 1}})), 1.0, 2e-3);
  EXPECT_NEAR(integral(makeCase("DisneyDiffuse", DisneyDiffuse{{1, 1, 1}, 0.5f, 0.5f, {1, 1, 1}})), 1.0, 2e-3);
}

TEST(BsdfConsistency, ReflectionIsReciprocal) {
  for (float r : kRoughnesses)
    for (const BsdfCase& c : casesAtRoughness(r)) {
      if (!c.reciprocal) continue;
      for (uint32_t i = 0; i < 500; ++i) {
        Vec3 a = sampleCosineHemisphere({randomUniform(i, 2, 0, 1), randomUniform(i, 2, 1, 1)});
        Vec3 b = sampleCosineHemisphere({randomUniform(i, 2, 2, 1), randomUniform(i, 2, 3, 1)});
        Vec3 fab = c.eval(a, b), fba = c.eval(b, a);
        ASSERT_LT(relativeDifference(luminance(fab), luminance(fba)), 1e-3f) << c.name << " r=" << r;
      }
    }
}

// Refraction obeys the generalised reciprocity of radiance transport: f(wo, wi) / eta_o^2 = f(wi, wo) / eta_i^2,
// eta_x the index on wx's side (here eta_o = 1, eta_i = eta). The reversed pair is evaluated from the other side, in
// the flipped frame.
TEST(BsdfConsistency, RefractionSatisfiesGeneralisedReciprocity) {
  for (float r : {0.1f, 0.5f})
    for (float eta : {1.5f, 1.0f / 1.5f}) {
      RoughDielectric forward{GgxDistribution::isotropic(r), eta, {1, 1, 1}};
      RoughDielectric backward{GgxDistribution::isotropic(r), 1.0f / eta, {1, 1, 1}};
      int checked = 0;
      for (uint32_t i = 0; i < 2000; ++i) {
        Vec3 wo = sampleCosineHemisphere({randomUniform(i, 3, 0, 1), randomUniform(i, 3, 1, 1)});
        Vec3 wi = sampleCosineHemisphere({randomUniform(i, 3, 2, 1), randomUniform(i, 3, 3, 1)});
        wi.z = -wi.z;
        float f = forward.eval(wo, wi).x;
        float reversed = backward.eval({-wi.x, -wi.y, -wi.z}, {-wo.x, -wo.y, -wo.z}).x;
        if (f == 0.0f && reversed == 0.0f) continue;
        // The two evaluations build the half vector from different float expressions: 5e-3 relative, and 1e-6
        // absolute for pairs at the edge of the lobe's support (values ~1e-8), where the half vector is nearly
        // tangent to one of the directions and cancellation dominates.
        ASSERT_NEAR(f * eta * eta, reversed, 5e-3f * std::fmax(f * eta * eta, reversed) + 1e-6f)
            << "eta " << eta << " r " << r;
        ++checked;
      }
      EXPECT_GT(checked, 100);
    }
}

TEST(DeltaLobes, MirrorReflectsAboutTheNormal) {
  MirrorBsdf mirror{{0.9f, 0.8f, 0.7f}};
  Vec3 wo = directionAt(40.0f, 75.0f);
  BsdfSample s = mirror.sample(wo, 0.3f, {0.1f, 0.9f});
  ASSERT_TRUE(s.valid && s.isDelta);
  EXPECT_NEAR(s.wi.x, -wo.x, 1e-6f);
  EXPECT_NEAR(s.wi.y, -wo.y, 1e-6f);
  EXPECT_NEAR(s.wi.z, wo.z, 1e-6f);
  Vec3 weight = s.f * (s.wi.z / s.pdf);
  EXPECT_NEAR(weight.x, 0.9f, 1e-6f);
  EXPECT_NEAR(weight.z, 0.7f, 1e-6f);
  EXPECT_EQ(luminance(mirror.eval(wo, s.wi)), 0.0f);
  EXPECT_EQ(mirror.pdf(wo, s.wi), 0.0f);
}

TEST(DeltaLobes, DielectricReflectsWithFresnelProbabilityAndRefractsBySnell) {
  for (float eta : {1.5f, 1.0f / 1.5f}) {
    SmoothDielectricBsdf glass{eta, {1, 1, 1}};
    Vec3 wo = directionAt(35.0f, 10.0f);
    float fresnel = fresnelDielectric(wo.z, eta);
    constexpr int kSamples = 100'000;
    int reflected = 0;
    for (uint32_t i = 0; i < kSamples; ++i) {
      BsdfSample s = glass.sample(wo, randomUniform(i, 4, 0, 1), {0.5f, 0.5f});
      ASSERT_TRUE(s.valid && s.isDelta);
      if (s.wi.z > 0) {
        ++reflected;
        EXPECT_NEAR(s.wi.z, wo.z, 1e-6f);
      } else {
        float sinI = std::sqrt(1 - wo.z * wo.z), sinT = std::sqrt(1 - s.wi.z * s.wi.z);
        EXPECT_NEAR(sinI, eta * sinT, 1e-5f);  // Snell: n_o sin_o = n_i sin_i with n_o = 1
        EXPECT_NEAR(s.wi.x * wo.y - s.wi.y * wo.x, 0.0f, 1e-6f) << "stays in the plane of incidence";
        EXPECT_EQ(s.eta, eta);
      }
    }
    double sigma = std::sqrt(fresnel * (1 - fresnel) / kSamples);
    EXPECT_NEAR(double(reflected) / kSamples, fresnel, 5 * sigma);
  }
  // Beyond the critical angle inside the denser medium everything reflects.
  SmoothDielectricBsdf inside{1.0f / 1.5f, {1, 1, 1}};
  for (float u : {0.0f, 0.5f, 0.999f}) EXPECT_GT(inside.sample(directionAt(60.0f), u, {0, 0}).wi.z, 0.0f);
}

}  // namespace
}  // namespace candela::test
