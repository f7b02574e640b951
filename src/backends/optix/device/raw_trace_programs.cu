// The raw-trace mode's program: the traversal ceiling for the path tracer's ray mix.
#include "backends/optix/device/program_common.h"

using namespace candela;
using namespace candela::optix;

// Traces the recorded rays again, in the same order and with the same ray types, with no shading at all: the
// traversal ceiling for the path tracer's ray mix. Cut-outs run the same any-hit programs; their random bits
// (which only alpha blending reads) are the slot's index instead of the path's, which makes the same decisions
// with the same probabilities.
extern "C" __global__ void __raygen__rawTrace() {
  const uint32_t pixel = launchPixel();
  const uint32_t pixelCount = params.settings.width * params.settings.height;
  const OptixTracer tracer = sceneTracer();
  const uint32_t count = params.recording.counts[pixel];
  for (uint32_t i = 0; i < count; ++i) {
    const size_t slot = size_t(i) * pixelCount + pixel;
    const RecordedRay r = params.recording.rays[slot];
    const Ray ray{r.origin, r.direction, r.tMin, r.tMax};
    const uint32_t randomBits = uint32_t(slot);
    if (params.recording.rayTypes[slot] == kRadianceRay) {
      Hit hit;
      tracer.intersect(ray, hit, randomBits);
    } else {
      tracer.occluded(ray, randomBits);
    }
  }
  params.counters[pixel] = {count, 0};
}
