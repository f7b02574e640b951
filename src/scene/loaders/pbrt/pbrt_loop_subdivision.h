#pragma once
#include "scene/scene.h"

namespace candela {

// Loop subdivision of a triangle mesh (positions and indices), `levels` times, with the boundary rules of Loop's
// thesis as pbrt applies them (boundary vertices follow only their boundary neighbours), then every vertex moved
// to the limit surface as pbrt does. Stops before a level that would exceed kMaxSubdividedTriangles. Smooth
// vertex normals of the result come with it.
constexpr size_t kMaxSubdividedTriangles = size_t(1) << 24;
Mesh loopSubdivide(Mesh control, int levels);

}  // namespace candela
