#pragma once
// Whole renders with known answers, for any backend: a typed test suite that each backend's test target
// instantiates (tests/render/analytic_scenes_test.cpp for the CPU, tests/gpu for OptiX) with the same scenes,
// sizes, sample counts, seeds and significance, so that every backend meets the same tolerances.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>
#include <utility>

#include "scene/builtin_scenes.h"
#include "support/cutout_screen.h"
#include "support/punctual_light_scenes.h"
#include "support/render_statistics.h"

namespace candela::test {

// A backend, the sampler its paths draw from and the way they pick emissive triangles: the answers must hold for
// every combination.
template <class BackendType, SamplerKind kKind, LightSamplerKind kLightKind = LightSamplerKind::Bvh>
struct WithSampler {
  using Backend = BackendType;
  static constexpr SamplerKind kSampler = kKind;
  static constexpr LightSamplerKind kLightSampler = kLightKind;
};

// Both samplers with the default light BVH, and the power table with the Sobol sampler.
template <class BackendType>
using EverySampler =
    ::testing::Types<WithSampler<BackendType, SamplerKind::Sobol>, WithSampler<BackendType, SamplerKind::Independent>,
                     WithSampler<BackendType, SamplerKind::Sobol, LightSamplerKind::Power>>;

// Batches of the Sobol sampler are parts of one stratified sequence, not independent: their spread overstates
// the error of the overall mean, so the tests below stay valid for it, only more tolerant.
template <class Pairing>
class AnalyticScenes : public ::testing::Test {
 protected:
  static constexpr uint32_t kBatches = 32;
  static constexpr uint32_t kSamplesPerBatch = 8;
  static constexpr double kAlpha = 0.01;

  static PixelStatistics render(const Scene& scene, uint32_t size, uint32_t maxDepth, uint32_t rouletteDepth) {
    typename Pairing::Backend backend;
    backend.setScene(scene);
    RenderSettings settings;
    settings.sampler = Pairing::kSampler;
    settings.lightSampler = Pairing::kLightSampler;
    settings.width = settings.height = size;
    settings.maxDepth = maxDepth;
    settings.rouletteDepth = rouletteDepth;
    settings.seed = 7;
    backend.setSettings(settings);
    backend.setCamera(scene.camera.toCamera(1.0f));
    return renderBatches(backend, kBatches, kSamplesPerBatch);
  }

  static PixelStatistics renderScreen(ScreenCoverage coverage) {
    return render(makeCutoutScreen(coverage), 32, RenderSettings{}.maxDepth, RenderSettings{}.rouletteDepth);
  }
};

// The albedo and emission of the closed spheres.
inline constexpr std::pair<float, float> kClosedSpheres[] = {{0.5f, 0.5f}, {0.8f, 0.2f}, {0.2f, 1.0f}};

// The image mean of a cut-out screen render must be within this many standard errors of the answer: the
// screen tests are 3 (checker, blend, and the wrong answers, which must lie outside).
inline double screenThreshold(double alpha) { return twoSidedNormalQuantile(sidak(alpha, 3.0)); }

TYPED_TEST_SUITE_P(AnalyticScenes);

// Inside a closed enclosure that emits e and reflects diffusely with albedo a everywhere, radiance is
// e + a e + a^2 e + ... = e / (1 - a) in every direction. Russian roulette keeps the paths finite, so the
// depth limit is set far beyond any path that survives it.
//
// The per-pixel t-test needs batch means that are close to normal. Roulette from the first bounce keeps every
// path's weight at most 1 and satisfies that; the default (roulette after 3 bounces) gives rare, heavy samples
// whose per-pixel batches are not normal, so with it the test is on the image mean, where the central limit
// theorem holds over all pixels' samples together.
TYPED_TEST_P(AnalyticScenes, ClosedSphereEveryPixelIsEmissionOverOneMinusAlbedo) {
  for (auto [albedo, emission] : kClosedSpheres) {
    SCOPED_TRACE("albedo " + std::to_string(albedo) + ", emission " + std::to_string(emission));
    PixelStatistics stats = TestFixture::render(makeClosedEmissiveSphere(albedo, emission), 24, 1000, 1);
    float expected = emission / (1.0f - albedo);
    std::string worst;
    EXPECT_EQ(countRejectedPixels(stats, {expected, expected, expected}, TestFixture::kBatches, TestFixture::kAlpha,
                                  worst),
              0u)
        << worst;
    EXPECT_EQ(stats.invalidSamples, 0u);
  }
}

TYPED_TEST_P(AnalyticScenes, ClosedSphereImageMeanIsEmissionOverOneMinusAlbedoWithDefaultRoulette) {
  for (auto [albedo, emission] : kClosedSpheres) {
    SCOPED_TRACE("albedo " + std::to_string(albedo) + ", emission " + std::to_string(emission));
    PixelStatistics stats =
        TestFixture::render(makeClosedEmissiveSphere(albedo, emission), 24, 1000, RenderSettings{}.rouletteDepth);
    double expected = emission / (1.0 - albedo);
    ImageMean m = imageMean(stats.mean);
    // Pixels share one expected value, so their spread estimates the noise of each; 3 tests per parameter set.
    double z = twoSidedNormalQuantile(sidak(TestFixture::kAlpha, 3.0));
    EXPECT_LT(std::fabs(m.mean - expected), z * m.standardError) << m.mean << " +- " << m.standardError;
  }
}

// The tests above must be able to fail: the image-mean test sees a 3% error, the per-pixel test (which at
// 256 samples per pixel resolves only errors of several standard deviations of one pixel) a 30% error.
TYPED_TEST_P(AnalyticScenes, ClosedSphereDetectsWrongAnswers) {
  PixelStatistics stats = TestFixture::render(makeClosedEmissiveSphere(0.5f, 0.5f), 24, 1000, 1);
  ImageMean m = imageMean(stats.mean);
  EXPECT_GT(std::fabs(m.mean - 0.97), twoSidedNormalQuantile(sidak(TestFixture::kAlpha, 3.0)) * m.standardError);
  std::string worst;
  EXPECT_GT(countRejectedPixels(stats, {0.7f, 0.7f, 0.7f}, TestFixture::kBatches, TestFixture::kAlpha, worst), 0u);
}

// Punctual lights, sampled only by next-event estimation: a point light inside a closed sphere lights every
// pixel equally (support/punctual_light_scenes.h), and a render that drops the interreflections (a / pi I) or
// the light's solid-angle conversion is rejected.
TYPED_TEST_P(AnalyticScenes, PointLightInClosedSphereEveryPixelIsTheAnswer) {
  const float albedo = 0.5f, intensity = 2.0f;
  PixelStatistics stats = TestFixture::render(makePointLitSphere(albedo, intensity), 24, 1000, 1);
  const float expected = pointLitSphereRadiance(albedo, intensity);
  std::string worst;
  EXPECT_EQ(
      countRejectedPixels(stats, {expected, expected, expected}, TestFixture::kBatches, TestFixture::kAlpha, worst), 0u)
      << worst;
  EXPECT_EQ(stats.invalidSamples, 0u);
  ImageMean m = imageMean(stats.mean);
  EXPECT_LT(std::fabs(m.mean - expected), twoSidedNormalQuantile(sidak(TestFixture::kAlpha, 2.0)) * m.standardError)
      << m.mean << " +- " << m.standardError;
  const float directOnly = albedo * intensity / kPi;
  EXPECT_GT(countRejectedPixels(stats, {directOnly, directOnly, directOnly}, TestFixture::kBatches, TestFixture::kAlpha,
                                worst),
            0u);
}

// A directional light on a lone floor: no interreflection, so every sample of every pixel is the answer.
TYPED_TEST_P(AnalyticScenes, DirectionalLightOnFloorEveryPixelIsTheAnswer) {
  const float albedo = 0.5f, irradiance = 3.0f, cosAngle = 0.6f;
  PixelStatistics stats = TestFixture::render(makeDirectionallyLitFloor(albedo, irradiance, cosAngle), 16, 4,
                                              RenderSettings{}.rouletteDepth);
  const float expected = directionallyLitFloorRadiance(albedo, irradiance, cosAngle);
  std::string worst;
  EXPECT_EQ(
      countRejectedPixels(stats, {expected, expected, expected}, TestFixture::kBatches, TestFixture::kAlpha, worst), 0u)
      << worst;
}

// A floor made of a mix of two greys, chosen per shading point: every pixel sees the floor of the mean albedo,
// (1 - amount) first + amount second (pbrt-v4's convention), whether the amount is a number or a number times a
// texture. Per pixel the choices are noise about that mean; the image mean tests the mean more finely.
inline constexpr float kMixFirst = 0.9f, kMixSecond = 0.1f, kMixIrradiance = 3.0f, kMixCos = 0.6f;

inline Scene makeTestMixedFloor(float amount, std::optional<uint8_t> amountTexel) {
  return makeMixedFloor(kMixFirst, kMixSecond, amount, amountTexel, kMixIrradiance, kMixCos);
}

inline float mixedFloorRadiance(float amount) {
  return directionallyLitFloorRadiance((1.0f - amount) * kMixFirst + amount * kMixSecond, kMixIrradiance, kMixCos);
}

// The image-mean test of a mixed floor: 5 of them below.
inline void expectImageMean(const PixelStatistics& stats, float expected, double alpha) {
  ImageMean m = imageMean(stats);
  EXPECT_LT(std::fabs(m.mean - expected), twoSidedNormalQuantile(sidak(alpha, 5.0)) * m.standardError)
      << m.mean << " +- " << m.standardError << ", expected " << expected;
}

TYPED_TEST_P(AnalyticScenes, MixedFloorEveryPixelIsTheMeanOfItsMaterials) {
  const uint32_t maxDepth = 4, rouletteDepth = RenderSettings{}.rouletteDepth;
  for (float amount : {0.3f, 0.75f}) {
    SCOPED_TRACE("amount " + std::to_string(amount));
    PixelStatistics stats = TestFixture::render(makeTestMixedFloor(amount, std::nullopt), 16, maxDepth, rouletteDepth);
    const float expected = mixedFloorRadiance(amount);
    std::string worst;
    EXPECT_EQ(countRejectedPixels(stats, {expected, expected, expected}, TestFixture::kBatches, TestFixture::kAlpha,
                                  worst),
              0u)
        << worst;
    expectImageMean(stats, expected, TestFixture::kAlpha);
  }
  // A textured amount: 0.6 times a texel of 128/255.
  PixelStatistics stats = TestFixture::render(makeTestMixedFloor(0.6f, uint8_t(128)), 16, maxDepth, rouletteDepth);
  expectImageMean(stats, mixedFloorRadiance(0.6f * 128.0f / 255.0f), TestFixture::kAlpha);
}

// The tests above reject the answers of a mix chosen per triangle (each of the floor's two triangles one grey)
// and of a textured amount taken as 0.5.
TYPED_TEST_P(AnalyticScenes, MixedFloorDetectsWrongAnswers) {
  const uint32_t maxDepth = 4, rouletteDepth = RenderSettings{}.rouletteDepth;
  Scene perTriangle = makeTestMixedFloor(0.5f, std::nullopt);
  perTriangle.meshes[0].triangleMaterials = {0, 1};
  PixelStatistics stats = TestFixture::render(perTriangle, 16, maxDepth, rouletteDepth);
  const float expected = mixedFloorRadiance(0.5f);
  std::string worst;
  EXPECT_GT(countRejectedPixels(stats, {expected, expected, expected}, TestFixture::kBatches, TestFixture::kAlpha,
                                worst),
            0u);
  ImageMean textured =
      imageMean(TestFixture::render(makeTestMixedFloor(0.6f, uint8_t(128)), 16, maxDepth, rouletteDepth));
  EXPECT_GT(std::fabs(textured.mean - mixedFloorRadiance(0.5f)),
            twoSidedNormalQuantile(sidak(TestFixture::kAlpha, 5.0)) * textured.standardError);
}

// A white, non-absorbing object under a uniform environment of radiance 1 is invisible: every pixel is 1.
TYPED_TEST_P(AnalyticScenes, WhiteFurnaceEveryPixelIsOne) {
  PixelStatistics stats = TestFixture::render(makeWhiteFurnace(), 32, 64, RenderSettings{}.rouletteDepth);
  std::string worst;
  EXPECT_EQ(countRejectedPixels(stats, {1, 1, 1}, TestFixture::kBatches, TestFixture::kAlpha, worst), 0u) << worst;
  EXPECT_EQ(stats.invalidSamples, 0u);
}

// Half the sky reaches the floor through the screen, by an alpha-tested checker or by alpha blending, and
// the culled back faces hide none of it (support/cutout_screen.h): the image mean is half the floor's albedo.
// Shadow rays (light sampling) and bounce rays both cross the screen, so each query's cut-outs count.
TYPED_TEST_P(AnalyticScenes, CutoutScreenPassesHalfTheSky) {
  for (ScreenCoverage coverage : {ScreenCoverage::CheckerMask, ScreenCoverage::HalfBlend}) {
    SCOPED_TRACE(coverage == ScreenCoverage::CheckerMask ? "checker mask" : "alpha blend");
    PixelStatistics stats = TestFixture::renderScreen(coverage);
    ImageMean m = imageMean(stats);
    EXPECT_LT(std::fabs(m.mean - 0.5 * kScreenFloorAlbedo), screenThreshold(TestFixture::kAlpha) * m.standardError)
        << m.mean << " +- " << m.standardError;
    EXPECT_EQ(stats.invalidSamples, 0u);
  }
}

// The test above rejects the renders of the two wrong treatments of cut-outs, as solid and as absent, and an
// answer 3% off.
TYPED_TEST_P(AnalyticScenes, CutoutScreenDetectsWrongAnswers) {
  const double threshold = screenThreshold(TestFixture::kAlpha);
  for (ScreenCoverage coverage : {ScreenCoverage::Opaque, ScreenCoverage::Absent}) {
    SCOPED_TRACE(coverage == ScreenCoverage::Opaque ? "opaque screen" : "no screen");
    ImageMean m = imageMean(TestFixture::renderScreen(coverage));
    EXPECT_GT(std::fabs(m.mean - 0.5 * kScreenFloorAlbedo), threshold * m.standardError)
        << m.mean << " +- " << m.standardError;
  }
  ImageMean checker = imageMean(TestFixture::renderScreen(ScreenCoverage::CheckerMask));
  EXPECT_GT(std::fabs(checker.mean - 0.515 * kScreenFloorAlbedo), threshold * checker.standardError);
}

REGISTER_TYPED_TEST_SUITE_P(AnalyticScenes, ClosedSphereEveryPixelIsEmissionOverOneMinusAlbedo,
                            ClosedSphereImageMeanIsEmissionOverOneMinusAlbedoWithDefaultRoulette,
                            ClosedSphereDetectsWrongAnswers, PointLightInClosedSphereEveryPixelIsTheAnswer,
                            DirectionalLightOnFloorEveryPixelIsTheAnswer, WhiteFurnaceEveryPixelIsOne,
                            CutoutScreenPassesHalfTheSky, CutoutScreenDetectsWrongAnswers,
                            MixedFloorEveryPixelIsTheMeanOfItsMaterials, MixedFloorDetectsWrongAnswers);

}  // namespace candela::test
