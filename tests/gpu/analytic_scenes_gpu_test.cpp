// The analytic whole-render tests of tests/render/analytic_scenes_test.cpp on the OptiX backend, with the same
// scenes, sizes, sample counts, seeds and significance, so the GPU meets exactly the CPU's tolerances.
#include <gtest/gtest.h>

#include <cmath>

#include "gpu_render.h"
#include "support/render_statistics.h"

namespace candela {
namespace {

using test::countRejectedPixels;
using test::PixelStatistics;

constexpr uint32_t kBatches = 32;
constexpr uint32_t kSamplesPerBatch = 8;
constexpr double kAlpha = 0.01;

PixelStatistics render(const Scene& scene, uint32_t size, uint32_t maxDepth, uint32_t rouletteDepth) {
  RenderSettings settings = test::squareImage(size, 7);
  settings.maxDepth = maxDepth;
  settings.rouletteDepth = rouletteDepth;
  auto backend = test::makeBackend<OptixBackend>(scene, settings);
  return test::renderBatches(*backend, kBatches, kSamplesPerBatch);
}

// Radiance inside a closed emissive diffuse enclosure is e / (1 - a) everywhere (see the CPU test for the
// choice of roulette depth in the per-pixel and the image-mean tests).
class GpuClosedSphere : public ::testing::TestWithParam<std::pair<float, float>> {};

TEST_P(GpuClosedSphere, EveryPixelIsEmissionOverOneMinusAlbedo) {
  auto [albedo, emission] = GetParam();
  PixelStatistics stats = render(makeClosedEmissiveSphere(albedo, emission), 24, 1000, 1);
  float expected = emission / (1.0f - albedo);
  std::string worst;
  EXPECT_EQ(countRejectedPixels(stats, {expected, expected, expected}, kBatches, kAlpha, worst), 0u) << worst;
  EXPECT_EQ(stats.invalidSamples, 0u);
}

TEST_P(GpuClosedSphere, ImageMeanIsEmissionOverOneMinusAlbedoWithDefaultRoulette) {
  auto [albedo, emission] = GetParam();
  PixelStatistics stats =
      render(makeClosedEmissiveSphere(albedo, emission), 24, 1000, RenderSettings{}.rouletteDepth);
  double expected = emission / (1.0 - albedo);
  test::ImageMean m = test::imageMean(stats.mean);
  double z = test::twoSidedNormalQuantile(test::sidak(kAlpha, 3.0));
  EXPECT_LT(std::fabs(m.mean - expected), z * m.standardError) << m.mean << " +- " << m.standardError;
}

INSTANTIATE_TEST_SUITE_P(AlbedoAndEmission, GpuClosedSphere,
                         ::testing::Values(std::pair{0.5f, 0.5f}, std::pair{0.8f, 0.2f}, std::pair{0.2f, 1.0f}));

// The same tests reject wrong answers on GPU renders: a 3% error in the image mean, 30% per pixel.
TEST(GpuClosedSphere, DetectsWrongAnswers) {
  PixelStatistics stats = render(makeClosedEmissiveSphere(0.5f, 0.5f), 24, 1000, 1);
  test::ImageMean m = test::imageMean(stats.mean);
  EXPECT_GT(std::fabs(m.mean - 0.97), test::twoSidedNormalQuantile(test::sidak(kAlpha, 3.0)) * m.standardError);
  std::string worst;
  EXPECT_GT(countRejectedPixels(stats, {0.7f, 0.7f, 0.7f}, kBatches, kAlpha, worst), 0u);
}

TEST(GpuWhiteFurnace, EveryPixelIsOne) {
  PixelStatistics stats = render(makeWhiteFurnace(), 32, 64, RenderSettings{}.rouletteDepth);
  std::string worst;
  EXPECT_EQ(countRejectedPixels(stats, {1, 1, 1}, kBatches, kAlpha, worst), 0u) << worst;
  EXPECT_EQ(stats.invalidSamples, 0u);
}

}  // namespace
}  // namespace candela
