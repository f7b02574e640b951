#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "core/math.h"

namespace candela {

// Splits a polygon (its corners in order) into corners.size() - 2 triangles that keep its winding, appending
// their corner numbers (0-based, 3 per triangle) to `triangles`. A quad is cut along its shorter diagonal unless
// that diagonal lies outside it. Larger polygons are ear-clipped in the plane they face; a polygon too degenerate
// to clip is cut into a fan. Ear clipping is quadratic for ordinary polygons and cubic at worst, so it is bounded:
// a polygon with more than kMaxEarClippedCorners corners, or one that needs more than kEarTestsPerCorner corner
// tests per corner, is (from there on) cut into a fan, which covers a concave outline wrongly; then the function
// returns false, so that the caller can warn. Time is linear in the corners.
constexpr size_t kMaxEarClippedCorners = 256;
constexpr size_t kEarTestsPerCorner = 512;
bool triangulatePolygon(std::span<const Vec3> corners, std::vector<uint32_t>& triangles);

}  // namespace candela
