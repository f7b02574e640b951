#pragma once
#include "kernel/light_bounds.h"
#include "kernel/scene_view.h"

namespace candela {

// A bounded light (an emissive triangle, a point or a spot light; see SceneView) chosen for a shading point, with the
// probability of the choice; pmf 0 when none was.
struct SampledLight {
  uint32_t index = 0;
  float pmf = 0.0f;
};

// Descends the light BVH from the root, at each node taking a child with probability proportional to its
// importance for ctx and rescaling `u` for the next decision. Picks nothing where no light can reach ctx.
CANDELA_FN SampledLight sampleLightBvh(const SceneView& scene, LightSampleContext ctx, float u) {
  SampledLight picked;
  if (boundedLightCount(scene) == 0) return picked;
  uint32_t nodeIndex = 0;
  float pmf = 1.0f;
  for (;;) {
    const LightBvhNode& node = scene.lightBvh[nodeIndex];
    if (node.isLeaf) {
      // Below the root a leaf's importance is positive, or its parent would not have chosen it.
      if (nodeIndex > 0 || lightImportance(node.bounds, ctx) > 0.0f) picked = {node.childOrLight, pmf};
      return picked;
    }
    float first = lightImportance(scene.lightBvh[nodeIndex + 1].bounds, ctx);
    float second = lightImportance(scene.lightBvh[node.childOrLight].bounds, ctx);
    if (!(first + second > 0.0f)) return picked;
    float pFirst = first / (first + second);
    if (u < pFirst) {
      nodeIndex = nodeIndex + 1;
      u = detail::smallerOf(u / pFirst, 0.99999994f);
      pmf *= pFirst;
    } else {
      nodeIndex = node.childOrLight;
      u = detail::smallerOf((u - pFirst) / (1.0f - pFirst), 0.99999994f);
      // Not 1 - pFirst, which loses the digits of a rare second child: as lightBvhPmf() computes it.
      pmf *= second / (first + second);
    }
  }
}

// The probability with which sampleLightBvh() picks light `lightIndex` for ctx: the same choices, taken along
// the light's bit trail instead of by a random number.
CANDELA_FN float lightBvhPmf(const SceneView& scene, LightSampleContext ctx, uint32_t lightIndex) {
  uint64_t trail = scene.lightBitTrails[lightIndex];
  uint32_t nodeIndex = 0;
  float pmf = 1.0f;
  for (;;) {
    const LightBvhNode& node = scene.lightBvh[nodeIndex];
    if (node.isLeaf) return nodeIndex > 0 || lightImportance(node.bounds, ctx) > 0.0f ? pmf : 0.0f;
    float first = lightImportance(scene.lightBvh[nodeIndex + 1].bounds, ctx);
    float second = lightImportance(scene.lightBvh[node.childOrLight].bounds, ctx);
    if (!(first + second > 0.0f)) return 0.0f;
    bool takeSecond = (trail & 1u) != 0;
    pmf *= (takeSecond ? second : first) / (first + second);
    nodeIndex = takeSecond ? node.childOrLight : nodeIndex + 1;
    trail >>= 1;
  }
}

// The index in `lights` of the emissive triangle (instanceId, primitiveId), or lightCount where it is none
// (not emissive, or degenerate). The light table is ordered by instance, then primitive.
CANDELA_FN uint32_t findLightIndex(const SceneView& scene, uint32_t instanceId, uint32_t primitiveId) {
  uint32_t lo = 0, hi = scene.lightCount;  // the light, if any, lies in [lo, hi)
  while (lo < hi) {
    uint32_t mid = lo + (hi - lo) / 2;
    const LightTriangle& light = scene.lights[mid];
    bool before = light.instanceId < instanceId || (light.instanceId == instanceId && light.primitiveId < primitiveId);
    if (before) {
      lo = mid + 1;
    } else {
      hi = mid;
    }
  }
  if (lo < scene.lightCount && scene.lights[lo].instanceId == instanceId && scene.lights[lo].primitiveId == primitiveId)
    return lo;
  return scene.lightCount;
}

}  // namespace candela
