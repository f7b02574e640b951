#include <gtest/gtest.h>

#include <set>

#include "core/rng.h"
#include "support/chi2.h"

namespace candela {
namespace {

TEST(Rng, IsAPureFunctionOfItsInputs) {
  EXPECT_EQ(randomUniform(5, 9, 3, 1), randomUniform(5, 9, 3, 1));
  EXPECT_NE(randomUniform(5, 9, 3, 1), randomUniform(5, 9, 3, 2));
  EXPECT_NE(randomUniform(5, 9, 3, 1), randomUniform(5, 9, 4, 1));
  EXPECT_NE(randomUniform(5, 9, 3, 1), randomUniform(5, 10, 3, 1));
  EXPECT_NE(randomUniform(5, 9, 3, 1), randomUniform(6, 9, 3, 1));
}

TEST(Rng, StaysInTheUnitInterval) {
  for (uint32_t i = 0; i < 100000; ++i) {
    float u = randomUniform(i, i * 7u, i % 13u, 0xFFFFFFFFu);
    ASSERT_GE(u, 0.0f);
    ASSERT_LT(u, 1.0f);
  }
  EXPECT_LT(bitsToUnitFloat(0xFFFFFFFFu), 1.0f);
}

// Pairs of numbers must fill the unit square uniformly whichever input varies: consecutive dimensions of one
// sample, one dimension over consecutive samples, and neighbouring pixels.
enum class Pairing { Dimensions, Samples, Pixels };

class RngPairs : public ::testing::TestWithParam<Pairing> {};

TEST_P(RngPairs, AreUniformOnTheSquare) {
  uint32_t counter = 0;
  Pairing pairing = GetParam();
  test::Chi2Options options;
  options.binsX = options.binsY = 64;
  options.sampleCount = 400000;
  options.testCount = 3;
  auto sample = [&](double, double, double) -> std::optional<Vec2> {
    uint32_t i = counter++;
    switch (pairing) {
      case Pairing::Dimensions: return Vec2{randomUniform(17, i, 4, 3), randomUniform(17, i, 5, 3)};
      case Pairing::Samples: return Vec2{randomUniform(17, 2 * i, 4, 3), randomUniform(17, 2 * i + 1, 4, 3)};
      case Pairing::Pixels: return Vec2{randomUniform(2 * i, 9, 0, 3), randomUniform(2 * i + 1, 9, 0, 3)};
    }
    return std::nullopt;
  };
  test::Chi2Result r = test::chi2TestSquare(
      sample, [](double, double) { return 1.0; }, options);
  EXPECT_TRUE(r.passed) << r.message;
}

INSTANTIATE_TEST_SUITE_P(Inputs, RngPairs, ::testing::Values(Pairing::Dimensions, Pairing::Samples, Pairing::Pixels));

}  // namespace
}  // namespace candela
