#pragma once
#include <cstdint>
#include <vector>

#include "core/math.h"

namespace candela {

// Shading normals for triangles that came without any. A corner's normal is the angle-weighted mean of the
// normals of the triangles around its position that are smoothed with it: those of the same smoothing group
// when the triangle has one (OBJ "s 1"...), otherwise those of group 0 whose normal is within `creaseDegrees`
// of its own. A corner with nothing to smooth with gets the normal of its triangle.
// Time is O(n log n) in the corners: corners around a position are sorted by group and by face normal, and the
// crease test runs once per distinct face normal there. Where a position has more than a few hundred distinct
// face normals (a fan of many triangles), each is tested against the mean directions of a fixed set of cells of
// directions instead of against every other, which may smooth across the crease angle by a few degrees.
struct NormalGenerationInput {
  const std::vector<Vec3>* positions = nullptr;
  const uint32_t* cornerPositions = nullptr;  // 3 per triangle
  size_t triangleCount = 0;
  const uint32_t* smoothingGroups = nullptr;  // one per triangle, 0 = none
  const uint8_t* needsNormals = nullptr;      // one per triangle; others neither get nor give normals
  float creaseDegrees = 45.0f;
};

// One unit normal per corner (3 per triangle); corners of triangles that need none are left zero.
std::vector<Vec3> generateCornerNormals(const NormalGenerationInput& input);

}  // namespace candela
