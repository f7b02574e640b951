// The path tracer's megakernel, and the program that records its rays for the raw-trace mode: they share a pipeline
// (optix_backend.cpp says why).
#include "backends/optix/device/program_common.h"
#include "backends/optix/device/render_pixel.h"

using namespace candela;
using namespace candela::optix;

extern "C" __global__ void __raygen__render() { renderPixel<false>(); }

// Traces one sample per pixel like __raygen__render and records its rays; the image is left alone.
extern "C" __global__ void __raygen__record() {
  const uint2 xy = launchPixelXY();
  const uint32_t pixel = launchPixel();
  const RecordingTracer tracer(sceneTracer(), params.recording, pixel, params.settings.width * params.settings.height);
  PathResult path =
      renderPixelSample(params.scene, tracer, params.camera, params.settings, xy.x, xy.y, params.firstSample);
  params.recording.counts[pixel] = min(tracer.count(), params.recording.slotsPerPixel);
  params.counters[pixel] = {tracer.count(), isValidSample(path.radiance) ? 0u : 1u};
}
