#pragma once
// The megakernel's pixel: one thread follows its paths from ray to ray through the shared kernel. Included by the
// modules of the path tracer with and without AOVs, after program_common.h. Device code only.

namespace {

// Adds `samplesPerPixel` path samples to the pixel's sums in the film (kernel/film_accumulation.h), which drops and
// counts invalid ones; with kWithAovs the AOVs too; with kWithMedia through the scene's participating media.
template <bool kWithAovs, bool kWithMedia = false>
__device__ void renderPixel() {
  using namespace candela;
  const uint2 xy = launchPixelXY();
  const uint32_t pixel = launchPixel();
  const optix::OptixTracer tracer = sceneTracer();
  const PixelTally tally =
      accumulatePixel<kWithAovs>(params.film, pixel, params.firstSample, params.samplesPerPixel, [&](uint32_t s) {
        return renderPixelSample<kWithAovs, kWithMedia>(params.scene, tracer, params.camera, params.settings, xy.x,
                                                        xy.y, s);
      });
  params.counters[pixel] = {tally.rays, tally.invalidSamples};
}

}  // namespace
