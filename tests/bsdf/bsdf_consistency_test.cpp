// sample() and evalPdf() agree with eval() and pdf(); densities integrate to the probability that sampling succeeds;
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
        ASSERT_EQ(s.eta != 1.0f, s.wi.z < 0.0f && c.refracts) << c.name << ": eta belongs to refracted samples only";
      }
}

// evalPdf() is eval() and pdf() in one call: the same numbers, to float round-off, for every lobe and model at
// random pairs of directions over the whole sphere (wo below the surface too, where both are zero), and at
// sampled ones, which find the narrow lobes' peaks.
TEST(BsdfConsistency, EvalPdfIsEvalAndPdf) {
  for (float r : kRoughnesses)
    for (const BsdfCase& c : casesAtRoughness(r)) {
      int nonZero = 0;
      for (uint32_t i = 0; i < 4000; ++i) {
        Vec3 wo = sampleUniformSphere({randomUniform(i, 2, 0, 11), randomUniform(i, 2, 1, 11)});
        Vec3 wi = sampleUniformSphere({randomUniform(i, 2, 2, 11), randomUniform(i, 2, 3, 11)});
        if (i % 2 == 0) wo.z = std::fabs(wo.z);
        if (i % 4 == 0) {
          BsdfSample s =
              c.sample(wo, randomUniform(i, 2, 4, 11), {randomUniform(i, 2, 5, 11), randomUniform(i, 2, 6, 11)});
          if (s.valid) wi = s.wi;
        }
        BsdfEval e = c.evalPdf(wo, wi);
        Vec3 f = c.eval(wo, wi);
        float pdf = c.pdf(wo, wi);
        ASSERT_LT(relativeDifference(e.pdf, pdf), 1e-5f) << c.name << " r=" << r << " pdf " << e.pdf << " vs " << pdf;
        for (int k = 0; k < 3; ++k)
          ASSERT_LT(relativeDifference(e.f[k], f[k]), 1e-5f)
              << c.name << " r=" << r << " f " << e.f[k] << " vs " << f[k];
        nonZero += pdf > 0.0f && !isBlack(f);
      }
      EXPECT_GT(nonZero, 500) << c.name << " r=" << r;
    }
}

// The same through Bsdf, which builds the model of each material type once and dispatches to it, in a frame
// with a tangent and a shading normal apart from the geometric one.
TEST(BsdfConsistency, BsdfEvalPdfIsEvalAndPdfForEveryMaterialType) {
  Material materials[6];
  materials[0].type = MaterialType::Diffuse;
  materials[1].type = MaterialType::BlinnPhong;
  materials[1].specularColor = {0.3f, 0.3f, 0.3f};
  materials[1].shininess = 80.0f;
  materials[2].type = MaterialType::Pbr;
  materials[2].metallic = 0.4f;
  materials[2].roughness = 0.3f;
  materials[3] = disneyMaterial(0.4f);
  materials[3].metallic = 0.2f;
  materials[3].anisotropic = 0.5f;
  materials[3].clearcoat = 0.7f;
  materials[3].sheen = 0.5f;
  materials[3].specTrans = 0.3f;
  // KHR_materials_iridescence's film on either model.
  materials[4] = materials[2];
  materials[5] = materials[3];
  for (Material* iridescent : {&materials[4], &materials[5]}) {
    iridescent->iridescence = 0.8f;
    iridescent->iridescenceIor = 1.6f;
    iridescent->iridescenceThickness = 420.0f;
  }
  SurfaceInteraction si;
  si.geometricNormal = normalize(Vec3{0.1f, 0.2f, 1.0f});
  si.shadingNormal = normalize(Vec3{0.2f, 0.1f, 1.0f});
  si.tangent = normalize(Vec3{1.0f, -0.3f, 0.0f});
  for (const Material& m : materials) {
    int nonZero = 0;
    for (uint32_t i = 0; i < 4000; ++i) {
      Vec3 wo = sampleUniformSphere({randomUniform(i, 3, 0, 13), randomUniform(i, 3, 1, 13)});
      Vec3 wi = sampleUniformSphere({randomUniform(i, 3, 2, 13), randomUniform(i, 3, 3, 13)});
      Bsdf bsdf(m, si, wo);
      BsdfEval e = bsdf.evalPdf(wo, wi);
      Vec3 f = bsdf.eval(wo, wi);
      float pdf = bsdf.pdf(wo, wi);
      ASSERT_LT(relativeDifference(e.pdf, pdf), 1e-5f) << int(m.type);
      for (int k = 0; k < 3; ++k) ASSERT_LT(relativeDifference(e.f[k], f[k]), 1e-5f) << int(m.type);
      nonZero += pdf > 0.0f && !isBlack(f);
    }
    EXPECT_GT(nonZero, 500) << int(m.type);
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
  EXPECT_NEAR(integral(
                  makeCase("DiffuseTransmission", DiffuseTransmissionBsdf{{0.2f, 0.4f, 0.1f}, {0.5f, 0.1f, 0.3f}})),
              1.0, 2e-3);
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
