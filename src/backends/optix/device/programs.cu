// The OptiX programs: raygen runs the shared path-tracing kernel; closest-hit, any-hit and miss only answer ray
// queries.
#include <optix.h>

#include "backends/optix/device/optix_tracer.h"
#include "backends/optix/launch_params.h"
#include "kernel/film_accumulation.h"

using namespace candela;
using namespace candela::optix;

// Defined here, filled by optixLaunch; the pipeline names it in pipelineLaunchParamsVariableName.
extern "C" {
__constant__ LaunchParameters params;
}

namespace {

// The image pixel of this launch index: a launch covers the rows from params.firstRow on.
__device__ uint2 launchPixelXY() {
  const uint3 index = optixGetLaunchIndex();
  return make_uint2(index.x, index.y + params.firstRow);
}

__device__ uint32_t launchPixel() {
  const uint2 xy = launchPixelXY();
  return xy.y * params.settings.width + xy.x;
}

__device__ OptixTracer sceneTracer() { return OptixTracer(params.traversable, params.scene.hasCutouts != 0); }

}  // namespace

// Adds `samplesPerPixel` path samples to the pixel's sums in the film (kernel/film_accumulation.h), which drops and
// counts invalid ones; with kWithAovs the AOVs too.
template <bool kWithAovs>
__device__ void renderPixel() {
  const uint2 xy = launchPixelXY();
  const uint32_t pixel = launchPixel();
  const OptixTracer tracer = sceneTracer();
  const PixelTally tally =
      accumulatePixel<kWithAovs>(params.film, pixel, params.firstSample, params.samplesPerPixel, [&](uint32_t s) {
        return renderPixelSample<kWithAovs>(params.scene, tracer, params.camera, params.settings, xy.x, xy.y, s);
      });
  params.counters[pixel] = {tally.rays, tally.invalidSamples};
}

extern "C" __global__ void __raygen__render() { renderPixel<false>(); }
extern "C" __global__ void __raygen__renderWithAovs() { renderPixel<true>(); }

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

#include "backends/optix/device/wavefront_programs.h"

// The scene's instance of the hit triangle: the IAS instance's, or for a batch of meshes the instance of the
// build input the triangle came from (launch_params.h).
__device__ uint32_t hitInstance() {
  const uint32_t id = optixGetInstanceId();
  if (id < params.firstBatchId) return id;
  return params.batchInstances[(id - params.firstBatchId) * kMaxBatchInputs + optixGetSbtGASIndex()];
}

extern "C" __global__ void __closesthit__radiance() {
  const float2 barycentrics = optixGetTriangleBarycentrics();
  optixSetPayload_0(__float_as_uint(optixGetRayTmax()));
  optixSetPayload_1(__float_as_uint(barycentrics.x));
  optixSetPayload_2(__float_as_uint(barycentrics.y));
  optixSetPayload_3(hitInstance());
  optixSetPayload_4(optixGetPrimitiveIndex());
}

// Any-hit for both ray types, run only on triangles whose material uses alpha: drops the candidate hit when
// the ray passes through it. Register 0 holds the query's random bits on the way in. Back faces of materials
// that cull them never get here: traversal culls them.
extern "C" __global__ void __anyhit__passThrough() {
  const float2 barycentrics = optixGetTriangleBarycentrics();
  Hit hit;
  hit.b1 = barycentrics.x;
  hit.b2 = barycentrics.y;
  hit.instanceId = hitInstance();
  hit.primitiveId = optixGetPrimitiveIndex();
  if (passesThrough(
          params.scene, hit, [] { return false; }, optixGetPayload_0()))
    optixIgnoreIntersection();
}

extern "C" __global__ void __miss__shadow() { optixSetPayload_1(0); }
