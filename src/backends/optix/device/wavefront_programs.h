#pragma once
// The wavefront schedule's raygen programs (backends/optix/wavefront_schedule.h): per bounce one launch traces the
// radiance rays (the camera's, or those queued; and the previous bounce's shadow rays), one shades their hits
// (kernel/path_vertex.h) and queues shadow rays and next rays; once few paths are left, one launch follows them to
// their ends instead; a last launch adds the paths to the film. The queue launches may have more threads than their
// queue has entries (the host learns a queue's length a bounce late): threads beyond its length return at once.
// Only programs.cu includes this, after the launch parameters and the helpers it defines.
#include "backends/optix/wavefront_path_planes.h"

namespace {

// The queue slot of this thread: the queue launches are one-dimensional.
__device__ uint32_t queueSlot() { return optixGetLaunchIndex().x; }

// Slots in the radiance queue and the shadow queue of `counts` for the threads of the warp that append a ray to
// either (`ray`, `shadow`): one 64-bit atomic per warp for both. Every active thread of the warp must call it.
struct QueueSlots {
  uint32_t ray, shadow;
};

__device__ QueueSlots appendSlots(QueueCounts* counts, bool ray, bool shadow) {
  const unsigned active = __activemask();
  const unsigned rays = __ballot_sync(active, ray), shadows = __ballot_sync(active, shadow);
  const int leader = __ffs(active) - 1;
  uint32_t lane;
  asm("mov.u32 %0, %%laneid;" : "=r"(lane));
  unsigned long long base = 0;
  if (int(lane) == leader && (rays | shadows) != 0u)
    base = atomicAdd(reinterpret_cast<unsigned long long*>(counts),
                     (static_cast<unsigned long long>(__popc(shadows)) << 32) | unsigned(__popc(rays)));
  base = __shfl_sync(active, base, leader);
  const unsigned below = (1u << lane) - 1u;
  return {uint32_t(base) + uint32_t(__popc(rays & below)), uint32_t(base >> 32) + uint32_t(__popc(shadows & below))};
}

__device__ uint32_t word(float f) { return __float_as_uint(f); }
__device__ float real(uint32_t u) { return __uint_as_float(u); }

// The path of slot `path` samples the pixel it is named after, in the band of rows the launch covers.
__device__ PathSampler pathSampler(uint32_t path) {
  return PathSampler(params.firstRow * params.settings.width + path, params.firstSample, params.settings.seed,
                     params.settings.sampler);
}

// The path's state and its sampler's next dimension, from every plane.
__device__ PathState loadPath(const WavefrontBuffers& w, uint32_t path, uint32_t& dimension) {
  const uint32_t n = w.slots;
  WavefrontPath p;
#pragma unroll
  for (uint32_t plane = 0; plane < kPathPlanes; ++plane) unpackPathPlane(w.paths[plane * n + path], plane, p);
  dimension = p.dimension;
  return p.state;
}

// The plane the last launch reads (radiance and rays), which is all of a path that has ended. The trace launch adds
// the light of shadow rays to the radiance in its words x, y and z.
static_assert(packedAt(offsetof(WavefrontPath, state.radiance.x), kPathResultPlane, 0) &&
                  packedAt(offsetof(WavefrontPath, state.radiance.y), kPathResultPlane, 1) &&
                  packedAt(offsetof(WavefrontPath, state.radiance.z), kPathResultPlane, 2) &&
                  packedIn(offsetof(WavefrontPath, state.rays), kPathResultPlane),
              "the result plane holds the radiance in words x, y and z, and the ray count");
__device__ void storePathResult(const WavefrontBuffers& w, uint32_t path, const PathState& s) {
  w.paths[kPathResultPlane * w.slots + path] = packPathPlane({s, 0u}, kPathResultPlane);
}

__device__ void storePath(const WavefrontBuffers& w, uint32_t path, const PathState& s, uint32_t dimension) {
  const uint32_t n = w.slots;
  const WavefrontPath p{s, dimension};
#pragma unroll
  for (uint32_t plane = 0; plane < kPathPlanes; ++plane) w.paths[plane * n + path] = packPathPlane(p, plane);
}

// A ray and its path in two planes of words (radiance and shadow queues alike): origin + tMax, direction + path.
__device__ void storeRayWords(Words4* planes, uint32_t stride, uint32_t slot, const Ray& ray, uint32_t path) {
  planes[slot] = {word(ray.origin.x), word(ray.origin.y), word(ray.origin.z), word(ray.tMax)};
  planes[stride + slot] = {word(ray.direction.x), word(ray.direction.y), word(ray.direction.z), path};
}

__device__ Ray loadRayWords(const Words4* planes, uint32_t stride, uint32_t slot, uint32_t& path) {
  const Words4 a = planes[slot], b = planes[stride + slot];
  path = b.w;
  return {{real(a.x), real(a.y), real(a.z)}, {real(b.x), real(b.y), real(b.z)}, 0.0f, real(a.w)};
}

struct QueuedRay {
  Ray ray;
  uint32_t path;
  uint32_t bits;
};

__device__ QueuedRay loadRay(const WavefrontBuffers& w, uint32_t queue, uint32_t slot) {
  QueuedRay q;
  q.ray = loadRayWords(w.rays[queue], w.slots, slot, q.path);
  q.bits = params.scene.hasCutouts ? w.rayBits[queue][slot] : 0u;
  return q;
}

__device__ void storeRay(const WavefrontBuffers& w, uint32_t queue, uint32_t slot, const Ray& ray, uint32_t path,
                         uint32_t bits) {
  storeRayWords(w.rays[queue], w.slots, slot, ray, path);
  if (params.scene.hasCutouts) w.rayBits[queue][slot] = bits;
}

// The path of the ray in `slot` of the queue this launch reads, the ray, and the sampler where the path left it.
__device__ PathState loadQueuedPath(const WavefrontBuffers& w, uint32_t slot, QueuedRay& q, PathSampler& sampler) {
  q.ray = loadRayWords(w.rays[w.current], w.slots, slot, q.path);
  uint32_t dimension = 0;
  const PathState s = loadPath(w, q.path, dimension);
  sampler = pathSampler(q.path);
  sampler.setDimension(dimension);
  return s;
}

// What the trace launch found for the ray in `slot` (instanceId kMissedInstance: nothing).
__device__ Hit loadHit(const WavefrontBuffers& w, uint32_t slot) {
  const Words4 h = w.hits[slot];
  Hit hit;
  hit.t = real(h.x);
  hit.b1 = real(h.y);
  hit.b2 = real(h.z);
  hit.instanceId = h.w;
  hit.primitiveId = w.hitPrimitives[slot];
  return hit;
}

// The camera bounce's launches are two-dimensional, one thread per pixel, as the one-thread schedule's (OptiX
// maps neighbouring pixels to a warp, whose camera rays then traverse together), and each makes the pixel's camera
// ray (sample params.firstSample) from its numbers again rather than queueing it. The path's slot is its pixel's
// in the band of rows the launch covers. Returns false where the ray cannot be traced: the sample is dropped.
__device__ bool cameraRay(uint32_t& path, PathSampler& sampler, Ray& ray, uint32_t& bits) {
  const uint2 xy = launchPixelXY();
  path = launchPixel() - params.firstRow * params.settings.width;
  sampler = pathSampler(path);
  ray = pixelSampleRay(params.camera, params.settings, xy.x, xy.y, sampler);
  if (!isTraceableCameraRay(ray)) return false;
  bits = passThroughBits(params.scene, sampler);
  return true;
}

}  // namespace

// Traces the shadow rays the previous bounce's shading queued, adding the light of those that reach it to their
// paths (a path gets at most one shadow ray per bounce, so no atomics), then this bounce's radiance rays, keeping
// their hits. One launch for both spares a launch per bounce.
extern "C" __global__ void __raygen__pathTrace() {
  const WavefrontBuffers& w = params.wavefront;
  uint32_t slot = queueSlot();
  QueuedRay q;
  if (w.cameraBounce) {
    PathSampler sampler = pathSampler(0);
    if (!cameraRay(q.path, sampler, q.ray, q.bits)) return;
    slot = q.path;
  } else {
    const QueueCounts counts = w.counts[w.current];
    if (slot < counts.shadow) {
      uint32_t path = 0;
      const Ray ray = loadRayWords(w.shadows, w.slots, slot, path);
      const Words4 c = w.shadows[2 * w.slots + slot];
      if (!sceneTracer().occluded(ray, c.w)) {
        Words4& radiance = w.paths[kPathResultPlane * w.slots + path];
        radiance.x = word(real(radiance.x) + real(c.x));
        radiance.y = word(real(radiance.y) + real(c.y));
        radiance.z = word(real(radiance.z) + real(c.z));
      }
    }
    if (slot >= counts.radiance) return;
    q = loadRay(w, w.current, slot);
  }
  Hit hit;
  if (!sceneTracer().intersect(q.ray, hit, q.bits)) hit.instanceId = kMissedInstance;
  w.hits[slot] = {word(hit.t), word(hit.b1), word(hit.b2), hit.instanceId};
  w.hitPrimitives[slot] = hit.primitiveId;
}

// Shades the hits of the radiance rays the trace launch traced: the path's state is default at its camera ray
// (startPath), and an ended path stores only what the last launch reads.
extern "C" __global__ void __raygen__pathShade() {
  const WavefrontBuffers& w = params.wavefront;
  uint32_t slot = queueSlot();
  QueuedRay q;
  PathSampler sampler = pathSampler(0);
  PathState s;
  if (w.cameraBounce) {
    if (!cameraRay(q.path, sampler, q.ray, q.bits)) {
      storePathResult(w, q.path, PathState{});  // no rays traced: the last launch drops the sample
      return;
    }
    slot = q.path;
    s = startPath(cameraRayCone(params.camera, params.settings.height));
  } else {
    if (slot >= w.counts[w.current].radiance) return;
    s = loadQueuedPath(w, slot, q, sampler);
  }
  const Hit hit = loadHit(w, slot);
  PathAovState unused;
  ShadowQuery shadow;
  VertexScatter scatter;
  Ray ray = q.ray;
  uint32_t bits = 0;
  bool goesOn = shadeVertex<false>(params.scene, params.settings, s, unused, sampler, ray,
                                   hit.instanceId != kMissedInstance, hit, shadow, scatter);
  const bool shadows = goesOn && !isBlack(shadow.contribution);
  goesOn = goesOn && continuePath<false>(params.scene, params.settings, s, unused, sampler, scatter, ray, bits);
  if (goesOn)
    storePath(w, q.path, s, sampler.dimension());
  else
    storePathResult(w, q.path, s);
  const uint32_t next = 1 - w.current;
  const QueueSlots k = appendSlots(&w.counts[next], goesOn, shadows);
  if (shadows) {
    const Vec3& c = shadow.contribution;
    storeRayWords(w.shadows, w.slots, k.shadow, shadow.ray, q.path);
    w.shadows[2 * w.slots + k.shadow] = {word(c.x), word(c.y), word(c.z), shadow.bits};
  }
  if (goesOn) storeRay(w, next, k.ray, ray, q.path, bits);
}

// Follows the paths of the queue this launch reads to their ends, one thread a path, as the one-thread schedule
// does (kernel/integrator.h), from the hits the trace launch found. Once few paths are left, the launches of a
// bounce take about the latency of the slowest ray's traversal and leave the GPU mostly idle; one launch for all
// the bounces left overlaps them.
extern "C" __global__ void __raygen__pathTail() {
  const WavefrontBuffers& w = params.wavefront;
  const uint32_t slot = queueSlot();
  if (slot >= w.counts[w.current].radiance) return;
  QueuedRay q;
  PathSampler sampler = pathSampler(0);
  PathState s = loadQueuedPath(w, slot, q, sampler);
  const Hit hit = loadHit(w, slot);
  PathAovState unused;
  followPath<false, true>(params.scene, sceneTracer(), params.settings, s, unused, sampler, q.ray, 0u,
                          hit.instanceId != kMissedInstance, hit);
  storePathResult(w, q.path, s);
}

// One thread per pixel: the path's sample joins the film (kernel/film_accumulation.h), as __raygen__render adds its.
extern "C" __global__ void __raygen__pathFinish() {
  const uint32_t pixel = launchPixel();
  const uint32_t path = pixel - params.firstRow * params.settings.width;
  WavefrontPath ended;
  unpackPathPlane(params.wavefront.paths[kPathResultPlane * params.wavefront.slots + path], kPathResultPlane, ended);
  const PixelTally tally = accumulatePixel<false>(params.film, pixel, params.firstSample, 1, [&](uint32_t) {
    PathResult result = droppedSample();
    if (ended.state.rays != 0u) {  // rays traced: not a dropped camera ray
      result.radiance = ended.state.radiance;
      result.rays = ended.state.rays;
    }
    return result;
  });
  params.counters[pixel] = {tally.rays, tally.invalidSamples};
}
