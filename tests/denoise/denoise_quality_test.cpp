// How much closer to a converged image the denoisers bring a 4-sample render, on the CPU: relMSE against a
// 4096-sample reference of the same scene at 64x64, and whether the a-trous filter bleeds across an albedo edge.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "denoise_support.h"
#include "image/filters/atrous.h"
#include "image/filters/bilateral.h"
#include "scene/builtin_scenes.h"

namespace candela {
namespace {

constexpr uint32_t kSize = 64;
constexpr uint32_t kNoisySpp = 4;
constexpr uint32_t kReferenceSpp = 4096;

class DenoiseQuality : public ::testing::TestWithParam<const char*> {};

// One test per scene, so that each reference is rendered once (CTest runs every test in its own process).
TEST_P(DenoiseQuality, AtrousIsFourTimesAndBilateralIsCloserThanRaw) {
  Scene scene;
  ASSERT_TRUE(makeBuiltinScene(GetParam(), scene));
  const Image reference = test::renderWithAovs(scene, kSize, kSize, kReferenceSpp, 1000).image;
  const test::RenderWithAovs noisy = test::renderWithAovs(scene, kSize, kSize, kNoisySpp, 1);
  const double raw = test::relativeMse(noisy.image, reference);
  const double atrous = test::relativeMse(atrousDenoise(noisy.image, noisy.aovs, AtrousParams{}), reference);
  const double bilateral = test::relativeMse(bilateralFilter(noisy.image, BilateralParams{}), reference);
  std::printf("%s: relMSE raw %.4f, a-trous %.4f (%.1fx lower), bilateral %.4f (%.2fx lower)\n", GetParam(), raw,
              atrous, raw / atrous, bilateral, raw / bilateral);
  EXPECT_LE(4.0 * atrous, raw);
  EXPECT_LT(bilateral, raw);
}

INSTANTIATE_TEST_SUITE_P(Scenes, DenoiseQuality, ::testing::Values("cornell-box", "material-gallery"),
                         [](const auto& param) {
                           std::string name = param.param;
                           for (char& ch : name)
                             if (ch == '-') ch = '_';
                           return name;
                         });

// The card of test::albedoEdgeCard has radiance exactly equal to its albedo: 0.9 left of the middle column,
// 0.1 right of it. Two to four columns away from the edge on each side, the denoised image must keep its side's
// value: the mean there may differ from it by no more than four standard errors of the raw image's mean over
// the same pixels (a much looser bound than the filter needs; a blur that ignores the edge misses it by far).
struct EdgeBands {
  double darkMean = 0.0, brightMean = 0.0;
};

EdgeBands edgeBands(const Image& image) {
  EdgeBands b;
  double n = 0.0;
  for (uint32_t y = 0; y < image.height; ++y)
    for (uint32_t d = 2; d <= 4; ++d) {
      b.brightMean += image.at(kSize / 2 - 1 - d, y).y;
      b.darkMean += image.at(kSize / 2 + d, y).y;
      n += 1.0;
    }
  b.brightMean /= n;
  b.darkMean /= n;
  return b;
}

double bandStandardError(const Image& image, uint32_t firstColumn) {
  double sum = 0.0, sum2 = 0.0, n = 0.0;
  for (uint32_t y = 0; y < image.height; ++y)
    for (uint32_t x = firstColumn; x < firstColumn + 3; ++x) {
      const double v = image.at(x, y).y;
      sum += v;
      sum2 += v * v;
      n += 1.0;
    }
  const double mean = sum / n;
  return std::sqrt(std::fmax(0.0, sum2 / n - mean * mean) / n);
}

TEST(AtrousEdges, NoBleedingAcrossAHardAlbedoEdge) {
  const test::RenderWithAovs r = test::renderWithAovs(test::albedoEdgeCard(0.9f, 0.1f), kSize, kSize, kNoisySpp, 1);
  const double darkBound = 4.0 * bandStandardError(r.image, kSize / 2 + 2);
  const double brightBound = 4.0 * bandStandardError(r.image, kSize / 2 - 5);
  const EdgeBands denoised = edgeBands(atrousDenoise(r.image, r.aovs, AtrousParams{}));
  std::printf("dark side %.4f (bound 0.1 +- %.4f), bright side %.4f (bound 0.9 +- %.4f)\n", denoised.darkMean,
              darkBound, denoised.brightMean, brightBound);
  EXPECT_NEAR(denoised.darkMean, 0.1, darkBound);
  EXPECT_NEAR(denoised.brightMean, 0.9, brightBound);

  // The same bands after the filter with its edge-stopping turned off and no demodulation (a plain a-trous
  // blur): the test can tell bleeding apart.
  AtrousParams blind;
  blind.colorSigma = blind.normalSigma = blind.depthSigma = 1e6f;
  AovImages flat = r.aovs;
  for (Vec3& a : flat.albedo.pixels) a = {1, 1, 1};
  const EdgeBands blurred = edgeBands(atrousDenoise(r.image, flat, blind));
  EXPECT_GT(std::fabs(blurred.darkMean - 0.1), darkBound);
  EXPECT_GT(std::fabs(blurred.brightMean - 0.9), brightBound);
}

}  // namespace
}  // namespace candela
