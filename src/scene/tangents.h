#pragma once
#include <vector>

#include "scene/scene.h"

namespace candela {

// Per-vertex tangents for tangent-space normal maps, for meshes that carry texture coordinates but no tangents.
// Follows MikkTSpace (Mikkelsen 2008): each triangle's texture-space u direction is projected into the vertex
// normal's tangent plane, normalised, weighted by the corner angle (measured in that plane) and summed per
// vertex; w = +1 when the triangle's (u, -v) orientation is preserved, -1 when mirrored. v is negated because
// normal maps store +Y towards the top of the image, where v is 0. For well-behaved meshes (vertices split at
// UV seams and wherever mirrored UV islands meet) this gives MikkTSpace's result; where one vertex joins
// triangles of both orientations MikkTSpace would split it, and this keeps the orientation with the larger
// angle sum. Meshes without normals use angle-weighted face normals. Vertices no triangle gives a direction to
// (zero UV area) get an arbitrary tangent perpendicular to their normal.
std::vector<Vec4> generateTangents(const Mesh& mesh);

}  // namespace candela
