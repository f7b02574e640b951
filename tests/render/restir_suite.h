#pragma once
// ReSTIR DI (kernel/restir/restir_passes.h) on any backend, a typed test suite that each backend's test target
// instantiates (tests/render/restir_test.cpp for the CPU, tests/gpu/restir_gpu_test.cpp for OptiX): its images must
// agree with the known answers of analytic scenes and, per pixel and in the image mean, with renders without ReSTIR,
// within the statistical noise; the same tests must reject a wrong answer; the temporal reuse must reject history
// across disocclusions.
//
// ReSTIR shares samples between pixels (spatial reuse) and between the samples of a render (temporal reuse), so
// neither pixels nor batches of one render are independent. Every batch here is therefore a render of its own,
// restarted with its history dropped and its own sample indices; statistics are over those independent batches,
// and the image mean's standard error comes from the spread of the batches' image means, not from the pixels'.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "backends/backend.h"
#include "scene/builtin_scenes.h"
#include "support/many_small_lights.h"
#include "support/punctual_light_scenes.h"
#include "support/render_statistics.h"

namespace candela::test::restir {

inline constexpr double kAlpha = 0.01;

// Independent batches of one scene: per pixel, their mean and the variance of that mean; and each batch's image mean.
struct Batches {
  PixelStatistics pixels;
  std::vector<double> imageMeans;
  uint64_t invalidSamples = 0;
};

// How a batch's samples are rendered: into one film (a still: the temporal reuse does not run), or each into a film
// of its own, as a camera that moves restarts the film (each sample after the batch's first reuses the history).
enum class Films { One, OnePerSample };

template <class BackendType>
Batches renderBatches(const Scene& scene, RenderSettings settings, uint32_t batches, uint32_t samplesPerBatch,
                      Films films = Films::One) {
  BackendType backend;
  backend.setScene(scene);
  const Camera camera = scene.camera.toCamera(float(settings.width) / float(settings.height));
  std::vector<Image> means;
  Batches out;
  for (uint32_t b = 0; b < batches; ++b) {
    backend.setSettings(settings);  // drops the film and ReSTIR's history
    backend.setCamera(camera);
    backend.setNextSampleIndex(b * samplesPerBatch);
    if (films == Films::One) {
      out.invalidSamples += backend.render(samplesPerBatch).invalidSamples;
      means.push_back(backend.readImage());
    } else {
      Image sum(settings.width, settings.height);
      for (uint32_t s = 0; s < samplesPerBatch; ++s) {
        backend.setCamera(camera);  // a new film; the history stays
        backend.setNextSampleIndex(b * samplesPerBatch + s);
        out.invalidSamples += backend.render(1).invalidSamples;
        const Image frame = backend.readImage();
        for (size_t i = 0; i < sum.pixels.size(); ++i) sum.pixels[i] += frame.pixels[i] / float(samplesPerBatch);
      }
      means.push_back(sum);
    }
    out.imageMeans.push_back(imageMean(means.back()).mean);
  }
  const size_t n = means[0].pixels.size();
  out.pixels.mean = Image(means[0].width, means[0].height);
  out.pixels.varianceOfMean = Image(means[0].width, means[0].height);
  for (size_t i = 0; i < n; ++i) {
    Vec3 sum{};
    for (const Image& m : means) sum += m.pixels[i];
    const Vec3 mean = sum / float(batches);
    Vec3 squares{};
    for (const Image& m : means) squares += (m.pixels[i] - mean) * (m.pixels[i] - mean);
    out.pixels.mean.pixels[i] = mean;
    out.pixels.varianceOfMean.pixels[i] = squares / float((batches - 1) * batches);
  }
  return out;
}

struct MeanAndError {
  double mean = 0.0, standardError = 0.0;
};

inline MeanAndError batchMean(const std::vector<double>& values, double scale = 1.0) {
  double sum = 0.0, squares = 0.0;
  for (double v : values) sum += v * scale;
  const double n = double(values.size()), mean = sum / n;
  for (double v : values) squares += (v * scale - mean) * (v * scale - mean);
  return {mean, std::sqrt(squares / (n - 1.0) / n)};
}

// Whether two independent renders' image means differ by more than the noise allows (Welch's t at `tests` tests).
inline bool imageMeansDiffer(const Batches& a, const Batches& b, double tests, double scaleOfB = 1.0) {
  const MeanAndError ma = batchMean(a.imageMeans), mb = batchMean(b.imageMeans, scaleOfB);
  const double t = std::fabs(ma.mean - mb.mean) / std::hypot(ma.standardError, mb.standardError);
  const double dof = double(std::min(a.imageMeans.size(), b.imageMeans.size()) - 1);
  return t > studentTTwoSidedQuantile(sidak(kAlpha, tests), dof);
}

// Pixel channels where two independent renders disagree (Welch's t per channel, Sidak over all of them).
inline size_t countDisagreeingPixels(const Batches& a, const Batches& b, uint32_t batches, std::string& worst,
                                     float scaleOfB = 1.0f) {
  const size_t n = a.pixels.mean.pixels.size();
  const double threshold = studentTTwoSidedQuantile(sidak(kAlpha, 3.0 * double(n)), double(batches - 1));
  size_t rejected = 0;
  double largest = 0.0;
  for (size_t i = 0; i < n; ++i) {
    const float ma[3] = {a.pixels.mean.pixels[i].x, a.pixels.mean.pixels[i].y, a.pixels.mean.pixels[i].z};
    const float mb[3] = {b.pixels.mean.pixels[i].x, b.pixels.mean.pixels[i].y, b.pixels.mean.pixels[i].z};
    const float va[3] = {a.pixels.varianceOfMean.pixels[i].x, a.pixels.varianceOfMean.pixels[i].y,
                         a.pixels.varianceOfMean.pixels[i].z};
    const float vb[3] = {b.pixels.varianceOfMean.pixels[i].x, b.pixels.varianceOfMean.pixels[i].y,
                         b.pixels.varianceOfMean.pixels[i].z};
    for (int c = 0; c < 3; ++c) {
      const double d = double(ma[c]) - double(mb[c]) * scaleOfB;
      const double se = std::sqrt(double(va[c]) + double(vb[c]) * scaleOfB * scaleOfB);
      if (d == 0.0) continue;
      const double t = se > 0.0 ? std::fabs(d) / se : kInf;
      if (t > threshold) ++rejected;
      if (t > largest) {
        largest = t;
        worst = "pixel " + std::to_string(i) + " channel " + std::to_string(c) + ": " + std::to_string(ma[c]) + " vs " +
                std::to_string(mb[c] * scaleOfB) + ", t = " + std::to_string(t);
      }
    }
  }
  return rejected;
}

inline RenderSettings settingsFor(RestirMode mode, uint32_t width, uint32_t height, uint32_t maxDepth,
                                  uint32_t rouletteDepth = RenderSettings{}.rouletteDepth) {
  RenderSettings s;
  s.width = width;
  s.height = height;
  s.maxDepth = maxDepth;
  s.rouletteDepth = rouletteDepth;
  s.seed = 11;
  s.restir = mode;
  return s;
}

template <class BackendType>
class RestirScenes : public ::testing::Test {
 protected:
  static Batches render(const Scene& scene, RenderSettings settings, uint32_t batches, uint32_t samplesPerBatch,
                        Films films = Films::One) {
    return renderBatches<BackendType>(scene, settings, batches, samplesPerBatch, films);
  }
};

TYPED_TEST_SUITE_P(RestirScenes);

// A closed sphere that emits e and reflects a everywhere: every pixel is e / (1 - a). Its direct light is that of
// hundreds of emissive triangles, every one a light of the BVH, and of the BSDF candidates that hit them.
TYPED_TEST_P(RestirScenes, ClosedEmissiveSphereEveryPixelIsTheAnswer) {
  const float albedo = 0.5f, emission = 0.5f, expected = emission / (1.0f - albedo);
  const uint32_t batches = 16;
  const Batches b = TestFixture::render(makeClosedEmissiveSphere(albedo, emission),
                                        settingsFor(RestirMode::Di, 24, 24, 1000, 1), batches, 8);
  std::string worst;
  EXPECT_EQ(countRejectedPixels(b.pixels, {expected, expected, expected}, batches, kAlpha, worst), 0u) << worst;
  const MeanAndError m = batchMean(b.imageMeans);
  EXPECT_LT(std::fabs(m.mean - expected), studentTTwoSidedQuantile(kAlpha, batches - 1) * m.standardError)
      << m.mean << " +- " << m.standardError;
  EXPECT_EQ(b.invalidSamples, 0u);
  // The same statistics reject an answer 3% off.
  EXPECT_GT(std::fabs(m.mean - 0.97 * expected), studentTTwoSidedQuantile(kAlpha, batches - 1) * m.standardError);
}

// A white furnace: a white diffuse sphere under a uniform sky of 1 is 1 everywhere; its direct light is the
// environment's, sampled by light sampling and by the BSDF candidate.
TYPED_TEST_P(RestirScenes, WhiteFurnaceEveryPixelIsOne) {
  const uint32_t batches = 16;
  const Batches b = TestFixture::render(makeWhiteFurnace(), settingsFor(RestirMode::Di, 24, 24, 1000, 1), batches, 8);
  std::string worst;
  EXPECT_EQ(countRejectedPixels(b.pixels, {1, 1, 1}, batches, kAlpha, worst), 0u) << worst;
  const MeanAndError m = batchMean(b.imageMeans);
  EXPECT_LT(std::fabs(m.mean - 1.0), studentTTwoSidedQuantile(kAlpha, batches - 1) * m.standardError)
      << m.mean << " +- " << m.standardError;
  EXPECT_GT(std::fabs(m.mean - 0.97), studentTTwoSidedQuantile(kAlpha, batches - 1) * m.standardError);
}

// Punctual lights (counting measure in the reservoirs): a point light in a closed sphere, a directional light on a
// floor.
TYPED_TEST_P(RestirScenes, PunctualLightsGiveTheAnswers) {
  const uint32_t batches = 16;
  {
    const float albedo = 0.5f, intensity = 2.0f, expected = pointLitSphereRadiance(albedo, intensity);
    const Batches b = TestFixture::render(makePointLitSphere(albedo, intensity),
                                          settingsFor(RestirMode::Di, 24, 24, 1000, 1), batches, 8);
    std::string worst;
    EXPECT_EQ(countRejectedPixels(b.pixels, {expected, expected, expected}, batches, kAlpha, worst), 0u) << worst;
  }
  {
    // One light and no interreflection: every sample is the answer, up to rounding.
    const float expected = directionallyLitFloorRadiance(0.5f, 3.0f, 0.6f);
    const Batches b = TestFixture::render(makeDirectionallyLitFloor(0.5f, 3.0f, 0.6f),
                                          settingsFor(RestirMode::Di, 16, 16, 4), batches, 8);
    for (const Vec3& p : b.pixels.mean.pixels) ASSERT_NEAR(p.x, expected, 1e-4f * expected);
  }
}

// Hundreds of small lights over a floor with boxes casting shadows, rendered with ReSTIR into `films`: it agrees
// with the render without it, per pixel and in the image mean, and the same tests reject that render's image scaled
// by 0.97. The 1/M weights of the biased mode claim light points for neighbours that cannot see them, and darken the
// image near shadows: the image-mean test sees it.
template <class BackendType>
void expectManyLightsAgreeWithoutRestir(Films films) {
  const Scene scene = makeManySmallLights(300, 5);
  const uint32_t batches = 24, spp = 8;
  const Batches restir = renderBatches<BackendType>(scene, settingsFor(RestirMode::Di, 32, 24, 3), batches, spp, films);
  const Batches off = renderBatches<BackendType>(scene, settingsFor(RestirMode::Off, 32, 24, 3), batches, spp);
  std::string worst;
  EXPECT_EQ(countDisagreeingPixels(restir, off, batches, worst), 0u) << worst;
  const MeanAndError withRestir = batchMean(restir.imageMeans), without = batchMean(off.imageMeans);
  EXPECT_FALSE(imageMeansDiffer(restir, off, 2.0)) << withRestir.mean << " +- " << withRestir.standardError
                                                   << " against " << without.mean << " +- " << without.standardError;
  EXPECT_TRUE(imageMeansDiffer(restir, off, 2.0, 0.97));
  EXPECT_EQ(restir.invalidSamples, 0u);
  const Batches biased =
      renderBatches<BackendType>(scene, settingsFor(RestirMode::DiBiased, 32, 24, 3), batches, spp, films);
  EXPECT_TRUE(imageMeansDiffer(biased, off, 2.0));
}

TYPED_TEST_P(RestirScenes, ManyLightsAgreeWithoutRestir) { expectManyLightsAgreeWithoutRestir<TypeParam>(Films::One); }

// The same where every sample is a film of its own (a moving camera's frames), so that the temporal reuse runs.
TYPED_TEST_P(RestirScenes, ManyLightsAgreeWithoutRestirWhenEverySampleReusesTheHistory) {
  expectManyLightsAgreeWithoutRestir<TypeParam>(Films::OnePerSample);
}

REGISTER_TYPED_TEST_SUITE_P(RestirScenes, ClosedEmissiveSphereEveryPixelIsTheAnswer, WhiteFurnaceEveryPixelIsOne,
                            PunctualLightsGiveTheAnswers, ManyLightsAgreeWithoutRestir,
                            ManyLightsAgreeWithoutRestirWhenEverySampleReusesTheHistory);

}  // namespace candela::test::restir
