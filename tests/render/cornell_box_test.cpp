#include <gtest/gtest.h>

#include <cstring>

#include "backends/cpu/cpu_backend.h"
#include "scene/builtin_scenes.h"
#include "support/render_statistics.h"

namespace candela {
namespace {

struct Render {
  Image image;
  FrameStats stats;
};

Render renderCornellBox(uint32_t seed, uint32_t spp) {
  Scene scene = makeCornellBox();
  CpuBackend backend;
  backend.setScene(scene);
  RenderSettings settings;
  settings.width = settings.height = 48;
  settings.seed = seed;
  backend.setSettings(settings);
  backend.setCamera(scene.camera.toCamera(1.0f));
  Render r;
  for (uint32_t s = 0; s < spp; ++s) {
    FrameStats f = backend.render(1);
    r.stats.rays += f.rays;
    r.stats.invalidSamples += f.invalidSamples;
  }
  r.image = backend.readImage();
  return r;
}

TEST(CornellBox, NoInvalidSamples) {
  Render r = renderCornellBox(1, 32);
  EXPECT_EQ(r.stats.invalidSamples, 0u);
  for (Vec3 p : r.image.pixels) ASSERT_TRUE(isFinite(p) && p.x >= 0.0f && p.y >= 0.0f && p.z >= 0.0f);
  EXPECT_GT(r.stats.rays, uint64_t(48 * 48 * 32));
}

TEST(CornellBox, SameSeedGivesTheSameImageBitForBit) {
  Render a = renderCornellBox(3, 8), b = renderCornellBox(3, 8);
  ASSERT_EQ(a.image.pixels.size(), b.image.pixels.size());
  EXPECT_EQ(std::memcmp(a.image.pixels.data(), b.image.pixels.data(), a.image.pixels.size() * sizeof(Vec3)), 0);
  EXPECT_EQ(a.stats.rays, b.stats.rays);
}

// Two seeds give independent estimates of the same image, so their per-pixel difference has mean zero and is
// independent across pixels: its mean over the image must pass a z-test against 0 (alpha = 0.01), and the
// images must not be identical.
TEST(CornellBox, ImageMeanIsStableAcrossSeeds) {
  Render a = renderCornellBox(11, 64), b = renderCornellBox(12, 64);
  Image difference(a.image.width, a.image.height);
  for (size_t i = 0; i < difference.pixels.size(); ++i) difference.pixels[i] = a.image.pixels[i] - b.image.pixels[i];
  test::ImageMean d = test::imageMean(difference);
  EXPECT_GT(d.standardError, 0.0) << "different seeds must give different noise";
  EXPECT_LT(std::fabs(d.mean), test::twoSidedNormalQuantile(0.01) * d.standardError)
      << "mean difference " << d.mean << " +- " << d.standardError;
  test::ImageMean m = test::imageMean(a.image);
  EXPECT_GT(m.mean, 0.05) << "the box must be lit";
}

}  // namespace
}  // namespace candela
