#pragma once
#include <cstdint>
#include <vector>

#include "kernel/scene_view.h"

namespace candela {

// The light BVH over a scene's bounded lights (emissive triangles, point and spot lights), in the layout
// SceneView::lightBvh and lightBitTrails describe. Empty without them.
struct LightBvh {
  std::vector<LightBvhNode> nodes;
  std::vector<uint64_t> bitTrails;  // per bounded light: the triangles, then the point and spot lights
};

// A one-sided emissive triangle's bounds: its box, its power (pi x luminance x area) and its normal, emitting
// over the hemisphere about it.
LightBounds triangleLightBounds(const LightTriangle& light);

// A point or spot light's bounds, as pbrt-v4's: its point, and the power 4 pi x luminance(I) for both, so that a
// spot's importance is its intensity's (as pbrt-v4: what its cone cuts off, the cone's bounds cut off). A point
// emits over the whole sphere; a spot's normals are its axis, widened by the inner cone's angle, and it emits up
// to the angle between the cones beyond them.
LightBounds punctualLightBounds(const PunctualLight& light);

// The smallest bounds holding both (as pbrt-v4's Union of LightBounds); bounds without power are empty.
LightBounds unite(const LightBounds& a, const LightBounds& b);

// Builds the BVH top down as pbrt-v4's BVHLightSampler: each node split where the sum of its children's costs
// (power times the solid angle they emit into times box area, penalising long thin boxes) is least.
// `punctual` holds point and spot lights only, which follow the triangles in the bounded lights' order.
LightBvh buildLightBvh(const std::vector<LightTriangle>& lights, const std::vector<PunctualLight>& punctual = {});

}  // namespace candela
