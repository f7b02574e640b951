// The film's accumulation (kernel/film_accumulation.h, the CPU backend's HostFilm): samples that are invalid or
// would overflow a pixel's sums are dropped and counted, AOVs and all, and means divide by the samples kept; the
// denoisers turn no finite input into NaN or infinity.
#include <gtest/gtest.h>

#include <cfloat>
#include <stdexcept>
#include <vector>

#include "backends/cpu/host_film.h"
#include "denoise_support.h"
#include "image/filters/atrous.h"
#include "image/filters/bilateral.h"
#include "kernel/film_accumulation.h"
#include "scene/builtin_scenes.h"

namespace candela {
namespace {

PathResult sample(Vec3 radiance, Vec3 emitted, Vec3 normal) {
  PathResult p;
  p.radiance = radiance;
  p.emitted = emitted;
  p.rays = 1;
  p.aovs.albedo = {0.5f, 0.5f, 0.5f};
  p.aovs.normal = normal;
  p.aovs.depth = 2.0f;
  return p;
}

bool allFinite(const Image& image) {
  for (const Vec3& p : image.pixels)
    if (!isFinite(p)) return false;
  return true;
}

// Three samples of 3e38 each are finite, but any two sum to infinity: the first is kept, the others are dropped and
// counted, and their AOVs (a normal that would show up in the mean) are dropped with them.
TEST(FilmAccumulation, DropsSamplesThatWouldOverflowTheSums) {
  HostFilm film;
  film.reset(1, 1, true);
  const std::vector<PathResult> samples = {sample({3e38f, 1, 1}, {}, {0, 0, 1}), sample({3e38f, 1, 1}, {}, {0, 1, 0}),
                                           sample({1, 1, 1}, {3e38f, 0, 0}, {0, 1, 0})};
  PixelTally tally = accumulatePixel<true>(film.view(), 0, 0, 2, [&](uint32_t i) { return samples[i]; });
  EXPECT_EQ(tally.rays, 2u);
  EXPECT_EQ(tally.invalidSamples, 1u);
  // A second call starts from the film's sums: radiance 3e38 + 1 and emission 0 + 3e38 are finite, so it is kept.
  tally = accumulatePixel<true>(film.view(), 0, 2, 1, [&](uint32_t) { return samples[2]; });
  EXPECT_EQ(tally.invalidSamples, 0u);
  const Image image = film.readImage();
  EXPECT_TRUE(allFinite(image));
  EXPECT_FLOAT_EQ(image.pixels[0].x, (3e38f + 1.0f) / 2.0f);
  const AovImages aovs = film.readAovs();
  EXPECT_EQ(aovs.normal.pixels[0].z, 0.5f);  // (1 + 0) / 2: the dropped sample's normal (0, 1, 0) is not in it
  EXPECT_EQ(aovs.normal.pixels[0].y, 0.5f);  // the kept third sample's
  EXPECT_FLOAT_EQ(aovs.emission.pixels[0].x, 1.5e38f);
}

TEST(FilmAccumulation, DropsNegativeAndNonFiniteSamplesAndDividesByTheSamplesKept) {
  HostFilm film;
  film.reset(1, 1, false);
  const std::vector<PathResult> samples = {sample({2, 2, 2}, {1, 1, 1}, {}), sample({-1, 0, 0}, {}, {}),
                                           sample({NAN, 0, 0}, {}, {}), sample({1, 1, 1}, {0, -1, 0}, {}),
                                           sample({4, 4, 4}, {}, {})};
  const PixelTally tally =
      accumulatePixel<false>(film.view(), 0, 0, uint32_t(samples.size()), [&](uint32_t i) { return samples[i]; });
  EXPECT_EQ(tally.invalidSamples, 3u);
  EXPECT_EQ(film.readImage().pixels[0].x, 3.0f);
  EXPECT_THROW(film.readEmission(), std::logic_error);  // recorded with the AOVs only
}

// The film keeps the luminance of the samples of odd index apart; the variance of the pixel's mean from its two
// halves is the squared difference of their means times n_e n_o / n^2 (times the overstatement of the sample
// variance's bound, to compare with it). Even samples of luminance 1 and 3 (mean 2),
// odd ones of 4 and 4 (mean 4): (2 - 4)^2 / 4 = 1. A dropped odd sample counts in neither half.
TEST(FilmAccumulation, KeepsTheOddSamplesApartForTheHalvesVariance) {
  HostFilm film;
  film.reset(1, 1, true);
  const std::vector<PathResult> samples = {sample({1, 1, 1}, {}, {0, 0, 1}), sample({4, 4, 4}, {}, {0, 0, 1}),
                                           sample({3, 3, 3}, {}, {0, 0, 1}), sample({NAN, 0, 0}, {}, {0, 0, 1}),
                                           sample({2, 2, 2}, {}, {0, 0, 1}), sample({4, 4, 4}, {}, {0, 0, 1})};
  accumulatePixel<true>(film.view(), 0, 0, uint32_t(samples.size()), [&](uint32_t i) { return samples[i]; });
  // Kept: even indices 0, 2, 4 (1, 3, 2: mean 2), odd 1, 5 (4, 4: mean 4); n = 5, n_e = 3, n_o = 2.
  const AovImages aovs = film.readAovs();
  EXPECT_NEAR(aovs.halvesVariance[0], 4.0f * 3.0f * 2.0f / 25.0f * varianceOverstatement(5), 1e-5f);

  film.reset(1, 1, true);
  accumulatePixel<true>(film.view(), 0, 0, 1, [&](uint32_t i) { return samples[i]; });
  EXPECT_EQ(film.readAovs().halvesVariance[0], kUnknownVariance);  // no odd sample yet
}

// A closed sphere of albedo 0 emitting 2e38 inside: every path's estimate is finite, any two sum to infinity. Each
// pixel keeps one sample and drops and counts three; the image must stay finite (no inf pixel reaches a file), and
// the denoisers must keep it so.
TEST(FilmAccumulation, ARenderOfFiniteSamplesThatWouldOverflowStaysFinite) {
  const Scene scene = makeClosedEmissiveSphere(0.0f, 2e38f);
  CpuBackend backend;
  backend.setScene(scene);
  RenderSettings settings;
  settings.width = settings.height = 8;
  backend.setSettings(settings);
  backend.setAovsEnabled(true);
  backend.setCamera(scene.camera.toCamera(1.0f));
  EXPECT_EQ(backend.render(4).invalidSamples, 3u * 64u);
  const test::RenderWithAovs r{backend.readImage(), backend.readAovs()};
  EXPECT_TRUE(allFinite(r.image));
  EXPECT_FLOAT_EQ(r.image.pixels[0].x, 2e38f);
  EXPECT_TRUE(allFinite(atrousDenoise(r.image, r.aovs, AtrousParams{})));
  EXPECT_TRUE(allFinite(bilateralFilter(r.image, r.aovs.emission, BilateralParams{})));
  EXPECT_TRUE(allFinite(bilateralFilter(r.image, BilateralParams{})));
}

// Images near the float maximum, with emission or without, on black and white albedo.
TEST(FilterRange, FiniteInputNeverBecomesNanOrInfinite) {
  const uint32_t w = 16, h = 16;
  Image color(w, h);
  AovImages aovs(w, h);
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      const size_t i = size_t(y) * w + x;
      const float v = (x + y) % 3 == 0 ? FLT_MAX : (x + y) % 3 == 1 ? 1e30f : 0.5f;
      color.pixels[i] = {v, v, v};
      aovs.emission.pixels[i] = x % 4 == 0 ? color.pixels[i] * 0.5f : Vec3{};
      aovs.albedo.pixels[i] = y % 2 == 0 ? Vec3{0, 0, 0} : Vec3{1, 1, 1};
      aovs.normal.pixels[i] = {0, 0, 1};
      aovs.depth[i] = 1.0f;
    }
  EXPECT_TRUE(allFinite(atrousDenoise(color, aovs, AtrousParams{})));
  EXPECT_TRUE(allFinite(bilateralFilter(color, aovs.emission, BilateralParams{})));
}

}  // namespace
}  // namespace candela
