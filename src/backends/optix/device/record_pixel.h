#pragma once
// The record program's pixel: traces one sample like the megakernel and records its rays for the raw-trace mode,
// leaving the image alone. Included, after program_common.h, by the path tracer's module, whose pipeline launches
// it, and by the AOV path tracer's, whose pipeline holds a copy only to keep its shape (program_use.cpp). Device
// code only.

namespace {

__device__ void recordPixel() {
  using namespace candela;
  using namespace candela::optix;
  const uint2 xy = launchPixelXY();
  const uint32_t pixel = launchPixel();
  const RecordingTracer tracer(sceneTracer(), params.recording, pixel, params.settings.width * params.settings.height);
  PathResult path =
      renderPixelSample(params.scene, tracer, params.camera, params.settings, xy.x, xy.y, params.firstSample);
  params.recording.counts[pixel] = min(tracer.count(), params.recording.slotsPerPixel);
  params.counters[pixel] = {tracer.count(), isValidSample(path.radiance) ? 0u : 1u};
}

}  // namespace
