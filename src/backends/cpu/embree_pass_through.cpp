#include "backends/cpu/embree_pass_through.h"

#include "kernel/pass_through.h"

namespace candela {

void rejectPassThroughHits(const RTCFilterFunctionNArguments* args) {
  const auto* context = reinterpret_cast<const PassThroughContext*>(args->context);
  for (unsigned int i = 0; i < args->N; ++i) {
    if (args->valid[i] == 0) continue;
    Hit hit;
    hit.b1 = RTCHitN_u(args->hit, args->N, i);
    hit.b2 = RTCHitN_v(args->hit, args->N, i);
    hit.instanceId = RTCHitN_instID(args->hit, args->N, i, 0);
    hit.primitiveId = RTCHitN_primID(args->hit, args->N, i);
    const SceneView& scene = *context->scene;
    auto backFace = [&] { return meetsBackFace(scene, hit, context->direction); };
    if (passesThrough(scene, hit, backFace, context->randomBits)) args->valid[i] = 0;
  }
}

}  // namespace candela
