// The OptiX programs: raygen runs the shared path-tracing kernel; closest-hit and miss only answer ray queries.
#include <optix.h>

#include "backends/optix/device/optix_tracer.h"
#include "backends/optix/launch_params.h"
#include "kernel/integrator.h"

using namespace candela;
using namespace candela::optix;

// Defined here, filled by optixLaunch; the pipeline names it in pipelineLaunchParamsVariableName.
extern "C" {
__constant__ LaunchParameters params;
}

namespace {

__device__ uint32_t launchPixel() {
  const uint3 index = optixGetLaunchIndex();
  return index.y * params.settings.width + index.x;
}

}  // namespace

// Adds `samplesPerPixel` path samples to the pixel's sum; NaN/Inf/negative samples are dropped and counted.
extern "C" __global__ void __raygen__render() {
  const uint3 index = optixGetLaunchIndex();
  const uint32_t pixel = launchPixel();
  const OptixTracer tracer(params.traversable);
  Vec3 sum{};
  uint32_t rays = 0, invalid = 0;
  for (uint32_t s = 0; s < params.samplesPerPixel; ++s) {
    PathResult path =
        renderPixelSample(params.scene, tracer, params.camera, params.settings, index.x, index.y, params.firstSample + s);
    rays += path.rays;
    if (isValidSample(path.radiance))
      sum += path.radiance;
    else
      ++invalid;
  }
  params.accumulation[pixel] += sum;
  params.counters[pixel] = {rays, invalid};
}

// Traces one sample per pixel like __raygen__render and records its rays; the image is left alone.
extern "C" __global__ void __raygen__record() {
  const uint3 index = optixGetLaunchIndex();
  const uint32_t pixel = launchPixel();
  const RecordingTracer tracer(params.traversable, params.recording, pixel,
                               params.settings.width * params.settings.height);
  PathResult path =
      renderPixelSample(params.scene, tracer, params.camera, params.settings, index.x, index.y, params.firstSample);
  params.recording.counts[pixel] = min(tracer.count(), params.recording.slotsPerPixel);
  params.counters[pixel] = {tracer.count(), isValidSample(path.radiance) ? 0u : 1u};
}

// Traces the recorded rays again, in the same order and with the same ray types, with no shading at all: the
// traversal ceiling for the path tracer's ray mix.
extern "C" __global__ void __raygen__rawTrace() {
  const uint32_t pixel = launchPixel();
  const uint32_t pixelCount = params.settings.width * params.settings.height;
  const OptixTracer tracer(params.traversable);
  const uint32_t count = params.recording.counts[pixel];
  for (uint32_t i = 0; i < count; ++i) {
    const size_t slot = size_t(i) * pixelCount + pixel;
    const RecordedRay r = params.recording.rays[slot];
    const Ray ray{r.origin, r.direction, r.tMin, r.tMax};
    if (params.recording.rayTypes[slot] == kRadianceRay) {
      Hit hit;
      tracer.intersect(ray, hit);
    } else {
      tracer.occluded(ray);
    }
  }
  params.counters[pixel] = {count, 0};
}

extern "C" __global__ void __closesthit__radiance() {
  const float2 barycentrics = optixGetTriangleBarycentrics();
  optixSetPayload_0(__float_as_uint(optixGetRayTmax()));
  optixSetPayload_1(__float_as_uint(barycentrics.x));
  optixSetPayload_2(__float_as_uint(barycentrics.y));
  optixSetPayload_3(optixGetInstanceId());
  optixSetPayload_4(optixGetPrimitiveIndex());
}

extern "C" __global__ void __miss__shadow() { optixSetPayload_0(0); }
