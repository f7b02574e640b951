#pragma once
#include "backends/cpu/embree.h"
#include "core/math.h"
#include "kernel/hit.h"

namespace candela {

// The ray queries of the kernel integrator, answered by Embree.
class EmbreeTracer {
 public:
  explicit EmbreeTracer(RTCScene scene) : scene_(scene) {}

  bool intersect(const Ray& ray, Hit& hit) const {
    RTCRayHit rh;
    setRay(rh.ray, ray);
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
#if CANDELA_EMBREE_VERSION >= 4
    rtcIntersect1(scene_, &rh);
#else
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    rtcIntersect1(scene_, &context, &rh);
#endif
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
    hit.t = rh.ray.tfar;
    hit.b1 = rh.hit.u;
    hit.b2 = rh.hit.v;
    hit.instanceId = rh.hit.instID[0];
    hit.primitiveId = rh.hit.primID;
    return true;
  }

  bool occluded(const Ray& ray) const {
    RTCRay r;
    setRay(r, ray);
#if CANDELA_EMBREE_VERSION >= 4
    rtcOccluded1(scene_, &r);
#else
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    rtcOccluded1(scene_, &context, &r);
#endif
    return r.tfar < 0.0f;  // Embree sets tfar to -inf when it finds an occluder
  }

 private:
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
};

}  // namespace candela
