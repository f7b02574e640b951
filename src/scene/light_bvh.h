#pragma once
#include <cstdint>
#include <vector>

#include "kernel/scene_view.h"

namespace candela {

// The light BVH over a scene's emissive triangles, in the layout SceneView::lightBvh and lightBitTrails describe.
// Empty without lights.
struct LightBvh {
  std::vector<LightBvhNode> nodes;
  std::vector<uint64_t> bitTrails;  // per light, in the order of the light table
};

// A one-sided emissive triangle's bounds: its box, its power (luminance times area) and its normal, emitting
// over the hemisphere about it.
LightBounds triangleLightBounds(const LightTriangle& light);

// The smallest bounds holding both (as pbrt-v4's Union of LightBounds); bounds without power are empty.
LightBounds unite(const LightBounds& a, const LightBounds& b);

// Builds the BVH top down as pbrt-v4's BVHLightSampler: each node split where the sum of its children's costs
// (power times the solid angle they emit into times box area, penalising long thin boxes) is least.
LightBvh buildLightBvh(const std::vector<LightTriangle>& lights);

}  // namespace candela
