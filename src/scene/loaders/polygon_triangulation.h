#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "core/math.h"

namespace candela {

// Splits a polygon (its corners in order) into corners.size() - 2 triangles that keep its winding, appending
// their corner numbers (0-based, 3 per triangle) to `triangles`. A quad is cut along its shorter diagonal unless
// that diagonal lies outside it. Larger polygons are ear-clipped in the plane they face; a polygon too degenerate
// to clip, or with more than kMaxEarClippedCorners corners (ear clipping is cubic in the worst case), is cut into
// a fan.
constexpr size_t kMaxEarClippedCorners = 256;
void triangulatePolygon(std::span<const Vec3> corners, std::vector<uint32_t>& triangles);

}  // namespace candela
