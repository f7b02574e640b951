// ReSTIR DI's four passes per sample (kernel/restir/restir_passes.h) as raygen programs of the megakernel kind: one
// thread per pixel, every pixel of one launch before any of the next. In the presampling launch each pixel's thread
// presamples its own light of its screen tile.
#include "backends/optix/device/program_common.h"
#include "kernel/restir/restir_passes.h"

using namespace candela;
using namespace candela::optix;

namespace {

template <bool kWithAovs>
__device__ void restirShadePixel() {
  const uint2 xy = launchPixelXY();
  const uint32_t pixel = launchPixel();
  const OptixTracer tracer = sceneTracer();
  const PixelTally tally = accumulatePixel<kWithAovs>(params.film, pixel, params.firstSample, 1, [&](uint32_t s) {
    return restirShadePass<kWithAovs>(params.scene, tracer, params.camera, params.settings, params.restir, xy.x, xy.y,
                                      s);
  });
  params.counters[pixel] = {tally.rays, tally.invalidSamples};
}

}  // namespace

extern "C" __global__ void __raygen__restirPrimary() {
  const uint2 xy = launchPixelXY();
  const uint32_t rays = restirPrimaryPass(params.scene, sceneTracer(), params.camera, params.settings, params.restir,
                                          xy.x, xy.y, params.firstSample);
  params.counters[launchPixel()] = {rays, 0u};
}

extern "C" __global__ void __raygen__restirPresample() {
  const uint2 xy = launchPixelXY();
  const uint32_t light = restirIndexInTile(params.settings, xy.x, xy.y);
  restirPresamplePass(params.scene, params.settings, params.restir, restirTileOf(params.settings, xy.x, xy.y), light,
                      light + 1, params.firstSample);
  params.counters[launchPixel()] = {0u, 0u};
}

extern "C" __global__ void __raygen__restirCandidates() {
  const uint2 xy = launchPixelXY();
  const uint32_t rays =
      restirCandidatePass(params.scene, sceneTracer(), params.settings, params.restir, xy.x, xy.y, params.firstSample);
  params.counters[launchPixel()] = {rays, 0u};
}

extern "C" __global__ void __raygen__restirShade() { restirShadePixel<false>(); }
extern "C" __global__ void __raygen__restirShadeWithAovs() { restirShadePixel<true>(); }
