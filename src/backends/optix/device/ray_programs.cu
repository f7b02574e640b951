// The programs that answer ray queries, shared by every pipeline: closest-hit (of triangles and of curves),
// any-hit (of triangles and of curves) and the shadow miss. Each
// pipeline's raygen programs are modules of their own (the other .cu files here).
#include "backends/optix/device/program_common.h"
#include "kernel/curve_attributes.h"

using namespace candela;
using namespace candela::optix;

namespace {

// The scene's instance of the hit triangle: the IAS instance's, or for a batch of meshes the instance of the
// build input the triangle came from (launch_params.h).
__device__ uint32_t hitInstance() {
  const uint32_t id = optixGetInstanceId();
  if (id < params.firstBatchId) return id;
  return params.batchInstances[(id - params.firstBatchId) * kMaxBatchInputs + optixGetSbtGASIndex()];
}

}  // namespace

extern "C" __global__ void __closesthit__radiance() {
  const float2 barycentrics = optixGetTriangleBarycentrics();
  optixSetPayload_0(__float_as_uint(optixGetRayTmax()));
  optixSetPayload_1(__float_as_uint(barycentrics.x));
  optixSetPayload_2(__float_as_uint(barycentrics.y));
  optixSetPayload_3(hitInstance());
  optixSetPayload_4(optixGetPrimitiveIndex());
}

// A curve's (kernel/curve.h): its parameter u along the segment in b1; the kernel rebuilds the rest of the surface
// from it and the ray (kernel/curve_attributes.h), as it does for Embree's hits. Meshes of curves are never
// batched, so their IAS instance id is their instance's.
extern "C" __global__ void __closesthit__curve() {
  optixSetPayload_0(__float_as_uint(optixGetRayTmax()));
  optixSetPayload_1(__float_as_uint(optixGetCurveParameter()));
  optixSetPayload_2(0);
  optixSetPayload_3(optixGetInstanceId());
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

// Any-hit on curves: drops a hit on a tube's inner wall, so that light a hair fibre transmits (its BSDF accounts for
// both walls) and shadow rays leave it, as the CPU backend's Embree filter does. Returns whether it kept the hit.
__device__ bool keepCurveHit() {
  Hit hit;
  hit.t = optixGetRayTmax();
  hit.b1 = optixGetCurveParameter();
  hit.instanceId = optixGetInstanceId();
  hit.primitiveId = optixGetPrimitiveIndex();
  const float3 origin = optixGetObjectRayOrigin(), direction = optixGetObjectRayDirection();
  if (!meetsTubeFromInside(params.scene, hit, {origin.x, origin.y, origin.z}, {direction.x, direction.y, direction.z}))
    return true;
  optixIgnoreIntersection();
  return false;
}

extern "C" __global__ void __anyhit__curveRadiance() { keepCurveHit(); }

// Shadow rays of a scene with curves traverse without OPTIX_RAY_FLAG_TERMINATE_ON_FIRST_HIT, under which OptiX finds
// curve hits with less precision than the inner-wall test needs (optix_tracer.h): a kept hit ends them here.
extern "C" __global__ void __anyhit__curveShadow() {
  if (keepCurveHit()) optixTerminateRay();
}

extern "C" __global__ void __miss__shadow() { optixSetPayload_1(0); }
