#pragma once
// The integrator's two ray queries answered by optixTrace. Device code only.
#include <optix.h>

#include "backends/optix/launch_params.h"
#include "kernel/hit.h"

namespace candela::optix {

class OptixTracer {
 public:
  // `cutouts`: the scene has cut-outs (SceneView::hasCutouts). Then rays cull back faces, which only the
  // triangles of materials that cull them allow (acceleration.cpp). `curves`: the scene has curves, whose any-hit
  // programs pass their inner walls; its shadow rays then go without OPTIX_RAY_FLAG_TERMINATE_ON_FIRST_HIT, under
  // which OptiX reports curve hits imprecisely (NVIDIA says so), and the curves' any-hit program ends them instead.
  // With neither, rays skip any-hit programs.
  __device__ OptixTracer(OptixTraversableHandle traversable, bool cutouts, bool curves)
      : traversable_(traversable),
        cutoutFlags_(cutouts  ? OPTIX_RAY_FLAG_CULL_BACK_FACING_TRIANGLES
                     : curves ? OPTIX_RAY_FLAG_NONE
                              : OPTIX_RAY_FLAG_DISABLE_ANYHIT),
        shadowFlags_(OPTIX_RAY_FLAG_DISABLE_CLOSESTHIT | cutoutFlags_ |
                     (curves ? OPTIX_RAY_FLAG_NONE : OPTIX_RAY_FLAG_TERMINATE_ON_FIRST_HIT)) {}

  // Closest hit: payload register 0 carries the random bits to the any-hit program (kernel/pass_through.h); then
  // the radiance closest-hit program writes t, barycentrics and ids into the five registers. The radiance miss
  // program is empty, so a miss leaves the instance register at its sentinel.
  __device__ bool intersect(const Ray& ray, Hit& hit, uint32_t randomBits) const {
    uint32_t t = randomBits, b1 = 0, b2 = 0, instance = kMissedInstance, primitive = 0;
    optixTrace(traversable_, toFloat3(ray.origin), toFloat3(ray.direction), ray.tMin, ray.tMax, 0.0f,
               OptixVisibilityMask(0xFF), cutoutFlags_, kRadianceRay, kRayTypeCount, kRadianceRay, t, b1, b2, instance,
               primitive);
    if (instance == kMissedInstance) return false;
    hit.t = __uint_as_float(t);
    hit.b1 = __uint_as_float(b1);
    hit.b2 = __uint_as_float(b2);
    hit.instanceId = instance;
    hit.primitiveId = primitive;
    return true;
  }

  // Any hit that does not pass through: traversal stops at the first one (but see the constructor) and runs no
  // closest-hit program; only the shadow miss program clears register 1. Register 0 carries the random bits, as
  // for intersect.
  __device__ bool occluded(const Ray& ray, uint32_t randomBits) const {
    uint32_t occluded = 1;
    optixTrace(traversable_, toFloat3(ray.origin), toFloat3(ray.direction), ray.tMin, ray.tMax, 0.0f,
               OptixVisibilityMask(0xFF), shadowFlags_, kShadowRay, kRayTypeCount, kShadowRay, randomBits, occluded);
    return occluded != 0;
  }

 private:
  __device__ static float3 toFloat3(Vec3 v) { return make_float3(v.x, v.y, v.z); }

  OptixTraversableHandle traversable_;
  unsigned int cutoutFlags_;
  unsigned int shadowFlags_;
};

// An OptixTracer that also writes every ray it traces into a RayRecording, for the raw-trace mode.
class RecordingTracer {
 public:
  __device__ RecordingTracer(const OptixTracer& tracer, const RayRecording& recording, uint32_t pixel,
                             uint32_t pixelCount)
      : tracer_(tracer), recording_(recording), pixel_(pixel), pixelCount_(pixelCount) {}

  __device__ bool intersect(const Ray& ray, Hit& hit, uint32_t randomBits) const {
    record(ray, kRadianceRay);
    return tracer_.intersect(ray, hit, randomBits);
  }
  __device__ bool occluded(const Ray& ray, uint32_t randomBits) const {
    record(ray, kShadowRay);
    return tracer_.occluded(ray, randomBits);
  }
  // Rays traced, recorded or not: more than slotsPerPixel means the recording is incomplete.
  __device__ uint32_t count() const { return count_; }

 private:
  __device__ void record(const Ray& ray, RayType type) const {
    if (count_ < recording_.slotsPerPixel) {
      size_t slot = size_t(count_) * pixelCount_ + pixel_;
      recording_.rays[slot] = {ray.origin, ray.tMin, ray.direction, ray.tMax};
      recording_.rayTypes[slot] = uint8_t(type);
    }
    ++count_;
  }

  OptixTracer tracer_;
  const RayRecording& recording_;
  uint32_t pixel_;
  uint32_t pixelCount_;
  mutable uint32_t count_ = 0;  // the integrator holds tracers by const reference
};

}  // namespace candela::optix
