#pragma once
// Curves (pbrt-v4's `curve` shape): cubic Bézier segments with a radius at each control point, as Embree's curve
// geometry and OptiX's built-in curve primitives take them. A mesh holds either triangles or curve segments, all of
// one type; its curves' control points are the per-mesh array curveVertices (xyz and the radius in w, four per
// segment), its ribbons' orientations curveNormals (one per control point), and each segment names its first
// control point and its material (scene_arrays.h).
#include <cstdint>

#include "core/math.h"

namespace candela {

// How a curve meets a ray (pbrt-v4's CurveType). A byte pattern read from a cache file is range-checked.
enum class CurveType : uint32_t {
  Flat,      // a band always facing the ray (Embree's flat curves), for hair seen from afar
  Cylinder,  // a round tube swept along the curve (Embree's round curves, OptiX's round cubic Bézier)
  Ribbon,    // a band oriented by the curve's normals (Embree's normal-oriented curves)
};
constexpr uint32_t kCurveTypeCount = 3;

// One cubic Bézier segment. firstVertex is the mesh-local index of its first control point in curveVertices (and,
// for ribbons, of its first normal in curveNormals); Embree's curve index buffer and OptiX's curve index buffer
// read it in place, with this struct's size as their stride.
struct CurveSegment {
  uint32_t firstVertex = 0;
  uint32_t material = 0;
  CurveType type = CurveType::Cylinder;
};

constexpr uint32_t kCurveControlPoints = 4;

// The cubic Bézier of control points p[0..3] at u in [0, 1], and its derivative.
CANDELA_FN Vec3 cubicBezier(const Vec3 p[4], float u) {
  const float s = 1.0f - u;
  return p[0] * (s * s * s) + p[1] * (3.0f * s * s * u) + p[2] * (3.0f * s * u * u) + p[3] * (u * u * u);
}
CANDELA_FN Vec3 cubicBezierDerivative(const Vec3 p[4], float u) {
  const float s = 1.0f - u;
  return (p[1] - p[0]) * (3.0f * s * s) + (p[2] - p[1]) * (6.0f * s * u) + (p[3] - p[2]) * (3.0f * u * u);
}
CANDELA_FN float cubicBezier(const float r[4], float u) {
  const float s = 1.0f - u;
  return r[0] * (s * s * s) + r[1] * (3.0f * s * s * u) + r[2] * (3.0f * s * u * u) + r[3] * (u * u * u);
}

}  // namespace candela
