// The wavefront schedule (backends/optix/wavefront_schedule.h) against the megakernel: the same samples, up to the
// rounding of fused multiply-adds, for scenes that exercise every part of the path state (delta bounces and their
// ray cones, cut-outs' pass-through bits, an environment), in whole images and in bands of rows, with the paths
// left after the camera bounce shaded a bounce at a time or followed to their ends in one launch; and auto's
// choice.
#include <gtest/gtest.h>

#include <cmath>

#include "gpu_render.h"
#include "support/cutout_screen.h"

namespace candela {
namespace {

struct Render {
  Image image;
  FrameStats stats;
};

// The wavefront's ways with the paths left after the camera bounce (OptixBackend::setWavefrontTailPaths): these
// test images are small enough for the default to take the tail launch at once.
enum class Tail : uint32_t { Never = 0, AtOnce = 0xFFFFFFFFu };

Render renderWith(PathSchedule schedule, const Scene& scene, uint32_t spp, uint32_t bands = 1, Tail tail = Tail::AtOnce,
                  uint32_t maxDepth = RenderSettings{}.maxDepth) {
  RenderSettings settings = test::squareImage(96, 7);
  settings.maxDepth = maxDepth;
  auto backend = test::makeBackend<OptixBackend>(scene, settings);
  backend->setPathSchedule(schedule);
  backend->setWavefrontTailPaths(uint32_t(tail));
  Render r;
  for (uint32_t band = 0; band < bands; ++band) {
    backend->setNextSampleIndex(0);  // every band takes the same samples, as each GPU's does under MultiGpuBackend
    const uint32_t first = settings.height * band / bands, last = settings.height * (band + 1) / bands;
    const FrameStats f = backend->renderRows(spp, first, last - first);
    r.stats.rays += f.rays;
    r.stats.invalidSamples += f.invalidSamples;
  }
  r.image = backend->readImage();
  return r;
}

// Fused multiply-adds round differently in the two schedules' programs, and where such a difference moves a ray
// across an edge (a cut-out's, a triangle's), that path and its pixel change: allowed in a few pixels only.
void expectSameSamples(const Render& megakernel, const Render& wavefront) {
  ASSERT_EQ(megakernel.image.pixels.size(), wavefront.image.pixels.size());
  size_t differing = 0;
  double sumA = 0.0, sumB = 0.0;
  for (size_t i = 0; i < megakernel.image.pixels.size(); ++i) {
    const Vec3 a = megakernel.image.pixels[i], b = wavefront.image.pixels[i];
    sumA += a.x + a.y + a.z;
    sumB += b.x + b.y + b.z;
    const float scale = fmaxf(1e-3f, fmaxf(maxComponent(a), maxComponent(b)));
    const Vec3 d = a - b;
    if (fmaxf(fabsf(d.x), fmaxf(fabsf(d.y), fabsf(d.z))) > 1e-3f * scale) ++differing;
  }
  EXPECT_LE(differing, megakernel.image.pixels.size() / 100) << differing << " pixels differ";
  EXPECT_NEAR(sumB / sumA, 1.0, 2e-3);
  EXPECT_EQ(megakernel.stats.invalidSamples, wavefront.stats.invalidSamples);
  EXPECT_NEAR(double(wavefront.stats.rays) / double(megakernel.stats.rays), 1.0, 1e-3);
}

void expectWavefrontTakesTheMegakernelsSamples(const Scene& scene, uint32_t maxDepth = RenderSettings{}.maxDepth) {
  const Render megakernel = renderWith(PathSchedule::Megakernel, scene, 8, 1, Tail::AtOnce, maxDepth);
  for (Tail tail : {Tail::Never, Tail::AtOnce}) {
    SCOPED_TRACE(tail == Tail::Never ? "a launch per bounce" : "the tail launch after the camera bounce");
    expectSameSamples(megakernel, renderWith(PathSchedule::Wavefront, scene, 8, 1, tail, maxDepth));
  }
}

TEST(WavefrontSchedule, TakesTheMegakernelsSamplesInTheCornellBox) {
  expectWavefrontTakesTheMegakernelsSamples(makeCornellBox());
}

TEST(WavefrontSchedule, TakesTheMegakernelsSamplesThroughMirrorsAndGlass) {
  expectWavefrontTakesTheMegakernelsSamples(makeCornellSpheres());
  expectWavefrontTakesTheMegakernelsSamples(makeMirrorCorridor());
}

TEST(WavefrontSchedule, TakesTheMegakernelsSamplesThroughCutouts) {
  for (test::ScreenCoverage coverage : {test::ScreenCoverage::CheckerMask, test::ScreenCoverage::HalfBlend})
    expectWavefrontTakesTheMegakernelsSamples(test::makeCutoutScreen(coverage));
}

// A thin lens draws two more numbers for each camera ray, which the camera bounce's two launches must both draw;
// at depth 1 (direct light only) every path ends in the first shading or tail launch.
TEST(WavefrontSchedule, TakesTheMegakernelsSamplesThroughALensAndAtDepthOne) {
  Scene lens = makeCornellBox();
  lens.camera.apertureRadius = 0.02f;  // 2 cm, the box's front plane in focus
  expectWavefrontTakesTheMegakernelsSamples(lens);
  expectWavefrontTakesTheMegakernelsSamples(makeCornellBox(), 1);
}

TEST(WavefrontSchedule, BandsOfRowsGiveTheWholeImagesSamples) {
  for (Tail tail : {Tail::Never, Tail::AtOnce}) {
    const Render whole = renderWith(PathSchedule::Wavefront, makeCornellSpheres(), 4, 1, tail);
    const Render banded = renderWith(PathSchedule::Wavefront, makeCornellSpheres(), 4, 3, tail);
    EXPECT_EQ(whole.stats.rays, banded.stats.rays);
    for (size_t i = 0; i < whole.image.pixels.size(); ++i) {
      ASSERT_EQ(whole.image.pixels[i].x, banded.image.pixels[i].x) << "pixel " << i;
      ASSERT_EQ(whole.image.pixels[i].y, banded.image.pixels[i].y) << "pixel " << i;
      ASSERT_EQ(whole.image.pixels[i].z, banded.image.pixels[i].z) << "pixel " << i;
    }
  }
}

// Auto takes the wavefront where paths run several bounces, the megakernel where camera rays mostly end at once.
TEST(WavefrontSchedule, AutoChoosesByTheRaysOfAProbeSample) {
  auto box = test::makeBackend<OptixBackend>(makeCornellBox(), test::squareImage(64, 1));
  box->render(1);
  EXPECT_NE(box->pathScheduleDescription().find("wavefront schedule"), std::string::npos)
      << box->pathScheduleDescription();

  Scene away = makeCornellBox();  // the camera turned round, into the empty space outside the box
  away.camera.target = away.camera.eye + (away.camera.eye - away.camera.target);
  auto outside = test::makeBackend<OptixBackend>(away, test::squareImage(64, 1));
  outside->render(1);
  EXPECT_NE(outside->pathScheduleDescription().find("megakernel schedule"), std::string::npos)
      << outside->pathScheduleDescription();
}

}  // namespace
}  // namespace candela
