// Whole renders with known answers, on the CPU backend.
#include <gtest/gtest.h>

#include "backends/cpu/cpu_backend.h"
#include "scene/builtin_scenes.h"
#include "support/render_statistics.h"

namespace candela {
namespace {

using test::countRejectedPixels;
using test::PixelStatistics;

constexpr uint32_t kBatches = 32;
constexpr uint32_t kSamplesPerBatch = 8;
constexpr double kAlpha = 0.01;

PixelStatistics render(const Scene& scene, uint32_t size, uint32_t maxDepth, uint32_t rouletteDepth) {
  CpuBackend backend;
  backend.setScene(scene);
  RenderSettings settings;
  settings.width = settings.height = size;
  settings.maxDepth = maxDepth;
  settings.rouletteDepth = rouletteDepth;
  settings.seed = 7;
  backend.setSettings(settings);
  backend.setCamera(scene.camera.toCamera(1.0f));
  return test::renderBatches(backend, kBatches, kSamplesPerBatch);
}

// Inside a closed enclosure that emits e and reflects diffusely with albedo a everywhere, radiance is
// e + a e + a^2 e + ... = e / (1 - a) in every direction. Russian roulette keeps the paths finite, so the
// depth limit is set far beyond any path that survives it.
//
// The per-pixel t-test needs batch means that are close to normal. Roulette from the first bounce keeps every
// path's weight at most 1 and satisfies that; the default (roulette after 3 bounces) gives rare, heavy samples
// whose per-pixel batches are not normal, so with it the test is on the image mean, where the central limit
// theorem holds over all pixels' samples together.
class ClosedSphere : public ::testing::TestWithParam<std::pair<float, float>> {};

TEST_P(ClosedSphere, EveryPixelIsEmissionOverOneMinusAlbedo) {
  auto [albedo, emission] = GetParam();
  PixelStatistics stats = render(makeClosedEmissiveSphere(albedo, emission), 24, 1000, 1);
  float expected = emission / (1.0f - albedo);
  std::string worst;
  EXPECT_EQ(countRejectedPixels(stats, {expected, expected, expected}, kBatches, kAlpha, worst), 0u) << worst;
  EXPECT_EQ(stats.invalidSamples, 0u);
}

TEST_P(ClosedSphere, ImageMeanIsEmissionOverOneMinusAlbedoWithDefaultRoulette) {
  auto [albedo, emission] = GetParam();
  PixelStatistics stats = render(makeClosedEmissiveSphere(albedo, emission), 24, 1000, RenderSettings{}.rouletteDepth);
  double expected = emission / (1.0 - albedo);
  test::ImageMean m = test::imageMean(stats.mean);
  // Pixels share one expected value, so their spread estimates the noise of each; 3 tests per parameter set.
  double z = test::twoSidedNormalQuantile(test::sidak(kAlpha, 3.0));
  EXPECT_LT(std::fabs(m.mean - expected), z * m.standardError) << m.mean << " +- " << m.standardError;
}

INSTANTIATE_TEST_SUITE_P(AlbedoAndEmission, ClosedSphere,
                         ::testing::Values(std::pair{0.5f, 0.5f}, std::pair{0.8f, 0.2f}, std::pair{0.2f, 1.0f}));

// The tests above must be able to fail: the image-mean test sees a 3% error, the per-pixel test (which at
// 256 samples per pixel resolves only errors of several standard deviations of one pixel) a 30% error.
TEST(ClosedSphere, DetectsWrongAnswers) {
  PixelStatistics stats = render(makeClosedEmissiveSphere(0.5f, 0.5f), 24, 1000, 1);
  test::ImageMean m = test::imageMean(stats.mean);
  EXPECT_GT(std::fabs(m.mean - 0.97), test::twoSidedNormalQuantile(test::sidak(kAlpha, 3.0)) * m.standardError);
  std::string worst;
  EXPECT_GT(countRejectedPixels(stats, {0.7f, 0.7f, 0.7f}, kBatches, kAlpha, worst), 0u);
}

// A white, non-absorbing object under a uniform environment of radiance 1 is invisible: every pixel is 1.
TEST(WhiteFurnace, EveryPixelIsOne) {
  PixelStatistics stats = render(makeWhiteFurnace(), 32, 64, RenderSettings{}.rouletteDepth);
  std::string worst;
  EXPECT_EQ(countRejectedPixels(stats, {1, 1, 1}, kBatches, kAlpha, worst), 0u) << worst;
  EXPECT_EQ(stats.invalidSamples, 0u);
}

}  // namespace
}  // namespace candela
