#include "backends/cpu/embree_curve_hits.h"

#include <cmath>

#include "backends/cpu/embree_pass_through.h"
#include "kernel/curve_attributes.h"

namespace candela {

void rejectCurveInsideHits(const RTCFilterFunctionNArguments* args) {
  for (unsigned int i = 0; i < args->N; ++i) {
    if (args->valid[i] == 0) continue;
    // Both in the curve's object space; Embree's Ng points out of the tube.
    const Vec3 direction{RTCRayN_dir_x(args->ray, args->N, i), RTCRayN_dir_y(args->ray, args->N, i),
                         RTCRayN_dir_z(args->ray, args->N, i)};
    const Vec3 normal{RTCHitN_Ng_x(args->hit, args->N, i), RTCHitN_Ng_y(args->hit, args->N, i),
                      RTCHitN_Ng_z(args->hit, args->N, i)};
    if (dot(direction, normal) > 0.0f) args->valid[i] = 0;
  }
}

void rejectFlatCurveSelfHits(const RTCFilterFunctionNArguments* args) {
  const SceneView& scene = *reinterpret_cast<const PassThroughContext*>(args->context)->scene;
  for (unsigned int i = 0; i < args->N; ++i) {
    if (args->valid[i] == 0) continue;
    Hit hit;
    hit.instanceId = RTCHitN_instID(args->hit, args->N, i, 0);
    hit.primitiveId = RTCHitN_primID(args->hit, args->N, i);
    const MeshRecord& mesh = scene.meshes[scene.instances[hit.instanceId].meshId];
    const float width =
        2.0f * curveRadiusAt(scene, mesh, hitCurveSegment(scene, hit), RTCHitN_u(args->hit, args->N, i));
    // The ray is in the curve's object space, where the width is measured: its direction need not be unit.
    const Vec3 direction{RTCRayN_dir_x(args->ray, args->N, i), RTCRayN_dir_y(args->ray, args->N, i),
                         RTCRayN_dir_z(args->ray, args->N, i)};
    if (RTCRayN_tfar(args->ray, args->N, i) * length(direction) < width) args->valid[i] = 0;
  }
}

}  // namespace candela
