#pragma once
#include "backends/cpu/embree.h"
#include "backends/cpu/embree_pass_through.h"
#include "core/math.h"
#include "kernel/hit.h"
#include "kernel/scene_view.h"

namespace candela {

// The ray queries of the kernel integrator, answered by Embree. `view` is the scene Embree's structures were
// built from; the filter functions on its cut-out geometry read it.
class EmbreeTracer {
 public:
  EmbreeTracer(RTCScene scene, const SceneView& view) : scene_(scene), view_(view) {}

  bool intersect(const Ray& ray, Hit& hit, uint32_t randomBits) const {
    RTCRayHit rh;
    setRay(rh.ray, ray);
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    PassThroughContext context = makeContext(ray, randomBits);
#if CANDELA_EMBREE_VERSION >= 4
    RTCIntersectArguments arguments;
    rtcInitIntersectArguments(&arguments);
    arguments.context = &context.base;
    rtcIntersect1(scene_, &rh, &arguments);
#else
    rtcIntersect1(scene_, &context.base, &rh);
#endif
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
    hit.t = rh.ray.tfar;
    hit.b1 = rh.hit.u;
    hit.b2 = rh.hit.v;
    hit.instanceId = rh.hit.instID[0];
    hit.primitiveId = rh.hit.primID;
    return true;
  }

  bool occluded(const Ray& ray, uint32_t randomBits) const {
    RTCRay r;
    setRay(r, ray);
    PassThroughContext context = makeContext(ray, randomBits);
#if CANDELA_EMBREE_VERSION >= 4
    RTCOccludedArguments arguments;
    rtcInitOccludedArguments(&arguments);
    arguments.context = &context.base;
    rtcOccluded1(scene_, &r, &arguments);
#else
    rtcOccluded1(scene_, &context.base, &r);
#endif
    return r.tfar < 0.0f;  // Embree sets tfar to -inf when it finds an occluder
  }

 private:
  PassThroughContext makeContext(const Ray& ray, uint32_t randomBits) const {
    PassThroughContext context;
#if CANDELA_EMBREE_VERSION >= 4
    rtcInitRayQueryContext(&context.base);
#else
    rtcInitIntersectContext(&context.base);
#endif
    context.scene = &view_;
    context.direction = ray.direction;
    context.randomBits = randomBits;
    return context;
  }

  static void setRay(RTCRay& r, const Ray& ray) {
    r.org_x = ray.origin.x;
    r.org_y = ray.origin.y;
    r.org_z = ray.origin.z;
    r.dir_x = ray.direction.x;
    r.dir_y = ray.direction.y;
    r.dir_z = ray.direction.z;
    r.tnear = ray.tMin;
    r.tfar = ray.tMax;
    r.time = 0.0f;
    r.mask = 0xFFFFFFFFu;
    r.id = 0;
    r.flags = 0;
  }

  RTCScene scene_;
  const SceneView& view_;
};

}  // namespace candela
