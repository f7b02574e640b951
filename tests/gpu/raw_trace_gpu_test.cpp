// The raw-trace timing mode traces exactly the path tracer's rays and leaves the image alone.
#include <gtest/gtest.h>

#include <cstring>

#include "gpu_render.h"
#include "support/cutout_screen.h"

namespace candela {
namespace {

TEST(GpuRawTrace, ReplaysTheRaysOfTheNextSample) {
  for (const Scene& scene :
       {makeCornellBox(), makeCornellSpheres(), test::makeCutoutScreen(test::ScreenCoverage::CheckerMask)}) {
    auto backend = test::makeBackend<OptixBackend>(scene, test::squareImage(64, 9));
    backend->render(1);
    Image before = backend->readImage();
    RawTraceTiming timing = backend->timeRawTrace(1, 3);
    EXPECT_EQ(backend->accumulatedSamples(), 1u);
    Image after = backend->readImage();
    EXPECT_EQ(std::memcmp(before.pixels.data(), after.pixels.data(), before.pixels.size() * sizeof(Vec3)), 0)
        << scene.name << ": the raw-trace mode must not touch the image";
    ASSERT_EQ(timing.deviceMilliseconds.size(), 3u);
    for (double ms : timing.deviceMilliseconds) EXPECT_GT(ms, 0.0);
    // The recorded sample is the one the next render call takes.
    FrameStats next = backend->render(1);
    EXPECT_EQ(timing.raysPerFrame, next.rays) << scene.name;
  }
}

}  // namespace
}  // namespace candela
