#pragma once
// Cut-outs on Embree: geometry whose materials can let rays through carries filter functions that reject the
// candidate hits kernel/pass_through.h says a ray passes through. What they need about the ray travels in the
// query's context, which Embree hands to the filter functions unchanged (the ray it hands them may be a copy in
// the instance's space).
#include "backends/cpu/embree.h"
#include "core/math.h"
#include "kernel/scene_view.h"

namespace candela {

struct PassThroughContext {
#if CANDELA_EMBREE_VERSION >= 4
  RTCRayQueryContext base;  // first, so that Embree's pointer to it points to the whole
#else
  RTCIntersectContext base;
#endif
  const SceneView* scene = nullptr;
  Vec3 direction;  // of the ray in world space
  uint32_t randomBits = 0;
};

// The filter function for both queries, intersect and occluded; single-ray queries with a PassThroughContext.
void rejectPassThroughHits(const RTCFilterFunctionNArguments* args);

}  // namespace candela
