// Chi-square tests of every non-delta lobe and model: the directions sample() draws must follow pdf().
#include <gtest/gtest.h>

#include "bsdf/bsdf_cases.h"
#include "support/chi2.h"

namespace candela::test {
namespace {

constexpr float kRoughnesses[] = {0.05f, 0.3f, 1.0f};
constexpr float kIncidentDegrees[] = {10.0f, 60.0f, 88.0f};  // 88 degrees: grazing
const size_t kCaseCount = casesAtRoughness(0.5f).size();
const int kTestCount = int(std::size(kRoughnesses) * std::size(kIncidentDegrees) * kCaseCount);

// 2 * 10^5 samples on 20 x 40 cells keep each test well under a second (the peaky lobes' cell integrals are
// the cost) while still rejecting a 10% error in a GGX width (Chi2RejectsAWrongWidth below).
Chi2Options options() {
  Chi2Options o;
  o.sampleCount = 200'000;
  o.binsX = 20;
  o.binsY = 40;
  o.testCount = kTestCount;
  return o;
}

Chi2Result runChi2(const BsdfCase& c, Vec3 wo, const Chi2Options& o) {
  return chi2TestSphere(
      [&](double u1, double u2, double u3) -> std::optional<Vec3> {
        BsdfSample s = c.sample(wo, float(u3), {float(u1), float(u2)});
        if (!s.valid) return std::nullopt;
        return s.wi;
      },
      [&](Vec3 wi) { return double(c.pdf(wo, wi)); }, o);
}

struct Chi2Param {
  float roughness;
  float incidentDegrees;
  size_t caseIndex;
};

class BsdfChi2 : public ::testing::TestWithParam<Chi2Param> {};

TEST_P(BsdfChi2, SamplesFollowPdf) {
  const Chi2Param& p = GetParam();
  BsdfCase c = casesAtRoughness(p.roughness)[p.caseIndex];
  Chi2Result r = runChi2(c, directionAt(p.incidentDegrees, 30.0f), options());
  EXPECT_TRUE(r.passed) << c.name << " at roughness " << p.roughness << ", " << p.incidentDegrees
                        << " degrees: " << r.message;
}

std::vector<Chi2Param> allParams() {
  std::vector<Chi2Param> params;
  for (float r : kRoughnesses)
    for (float a : kIncidentDegrees)
      for (size_t i = 0; i < kCaseCount; ++i) params.push_back({r, a, i});
  return params;
}

INSTANTIATE_TEST_SUITE_P(AllLobesAndModels, BsdfChi2, ::testing::ValuesIn(allParams()),
                         [](const ::testing::TestParamInfo<Chi2Param>& paramInfo) {
                           const Chi2Param& p = paramInfo.param;
                           return casesAtRoughness(p.roughness)[p.caseIndex].name + "_r" +
                                  std::to_string(int(p.roughness * 100)) + "_deg" +
                                  std::to_string(int(p.incidentDegrees));
                         });

// The test has power: sampling GGX normals 10% wider than the pdf describes is rejected.
TEST(BsdfChi2Power, RejectsAWrongWidth) {
  GgxReflection truth{GgxDistribution::isotropic(0.5f), {1, 1, 1}};
  GgxReflection wider{{truth.distribution.alphaX * 1.1f, truth.distribution.alphaY * 1.1f}, {1, 1, 1}};
  BsdfCase c = makeCase("wrong", truth);
  c.sample = [wider](Vec3 wo, float uc, Vec2 u) { return wider.sample(wo, uc, u); };
  Chi2Result r = runChi2(c, directionAt(45.0f), options());
  EXPECT_FALSE(r.passed) << r.message;
}

// ... and so is a lobe choice whose probabilities differ from the ones pdf() mixes with.
TEST(BsdfChi2Power, RejectsAMismatchedLobeChoice) {
  PbrBsdf model({0.8f, 0.6f, 0.4f}, 0.0f, 0.3f, 0.5f);
  BsdfCase c = makeCase("wrong", model);
  c.sample = [model](Vec3 wo, float uc, Vec2 u) { return model.sample(wo, uc * 0.8f, u); };
  Chi2Result r = runChi2(c, directionAt(45.0f), options());
  EXPECT_FALSE(r.passed) << r.message;
}

}  // namespace
}  // namespace candela::test
