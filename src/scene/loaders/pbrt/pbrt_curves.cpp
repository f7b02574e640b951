#include "scene/loaders/pbrt/pbrt_curves.h"

#include <cmath>
#include <string>

namespace candela {

namespace {

Vec3 lerpPoints(float t, Vec3 a, Vec3 b) { return a * (1.0f - t) + b * t; }

bool finitePoint(Vec3 p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

struct CurveShape {
  int degree = 3;
  bool bspline = false;
  size_t segments = 0;
};

// The basis, degree and segment count of `params`, refused where pbrt-v4 refuses them.
CurveShape curveShape(const PbrtParameters& params, size_t points) {
  CurveShape shape;
  shape.degree = params.getInt("degree", 3);
  if (shape.degree != 2 && shape.degree != 3)
    params.fail("curve: 'degree' must be 2 or 3, not " + std::to_string(shape.degree));
  const std::string basis = params.getString("basis", "bezier");
  if (basis != "bezier" && basis != "bspline") params.fail("curve: unknown basis '" + basis + "' (bezier or bspline)");
  shape.bspline = basis == "bspline";
  const size_t degree = size_t(shape.degree);
  if (shape.bspline) {
    if (points < degree + 1)
      params.fail("curve: a degree " + std::to_string(degree) + " b-spline needs at least " +
                  std::to_string(degree + 1) + " control points, not " + std::to_string(points));
    shape.segments = points - degree;
  } else {
    // The first segment takes degree + 1 points, each further one degree more (sharing the last).
    if (points < degree + 1 || (points - 1) % degree != 0)
      params.fail("curve: a degree " + std::to_string(degree) + " Bezier curve needs " + std::to_string(degree + 1) +
                  " + n * " + std::to_string(degree) + " control points, not " + std::to_string(points));
    shape.segments = (points - 1) / degree;
  }
  return shape;
}

CurveType curveType(const PbrtParameters& params) {
  const std::string type = params.getString("type", "flat");  // pbrt-v4's default
  if (type == "flat") return CurveType::Flat;
  if (type == "cylinder") return CurveType::Cylinder;
  if (type == "ribbon") return CurveType::Ribbon;
  params.fail("curve: unknown type '" + type + "' (flat, cylinder or ribbon)");
}

}  // namespace

std::array<Vec3, 4> elevateQuadraticBezierToCubic(const Vec3 p[3]) {
  return {p[0], lerpPoints(2.0f / 3.0f, p[0], p[1]), lerpPoints(1.0f / 3.0f, p[1], p[2]), p[2]};
}

std::array<Vec3, 3> quadraticBSplineToBezier(const Vec3 p[3]) {
  return {lerpPoints(0.5f, p[0], p[1]), p[1], lerpPoints(0.5f, p[1], p[2])};
}

std::array<Vec3, 4> cubicBSplineToBezier(const Vec3 p[4]) {
  // Blossoms: the b-spline's points are p012, p123, p234, p345; the Bézier's p222, p223, p233, p333.
  const Vec3 p122 = lerpPoints(2.0f / 3.0f, p[0], p[1]);
  const Vec3 p223 = lerpPoints(1.0f / 3.0f, p[1], p[2]);
  const Vec3 p233 = lerpPoints(2.0f / 3.0f, p[1], p[2]);
  const Vec3 p334 = lerpPoints(1.0f / 3.0f, p[2], p[3]);
  return {lerpPoints(0.5f, p122, p223), p223, p233, lerpPoints(0.5f, p233, p334)};
}

size_t pbrtCurveBytes(const PbrtParameters& params) {
  const PbrtParameter* points = params.find("P");
  if (!points) return 0;
  // At most one segment per control point, of 4 vertices, 4 normals and the segment itself.
  const size_t segments = points->numbers.size() / 3;
  return segments * (kCurveControlPoints * (sizeof(Vec4) + sizeof(Vec3)) + sizeof(CurveSegment));
}

PbrtCurve makePbrtCurve(const PbrtParameters& params) {
  const std::vector<Vec3> points = params.getVec3s("P");
  if (points.empty()) params.fail("curve without 'P'");  // the parser has refused numbers that are not finite
  const CurveShape shape = curveShape(params, points.size());
  PbrtCurve curve;
  curve.type = curveType(params);

  const float width = params.getFloat("width", 1.0f);
  const float width0 = params.getFloat("width0", width), width1 = params.getFloat("width1", width);
  for (float w : {width, width0, width1})
    if (!(w > 0.0f) || !std::isfinite(w)) params.fail("curve: widths must be finite and positive");

  std::vector<Vec3> normals = params.getVec3s("N");
  if (curve.type == CurveType::Ribbon) {
    if (normals.size() != shape.segments + 1)
      params.fail("curve: a ribbon of " + std::to_string(shape.segments) + " segments needs " +
                  std::to_string(shape.segments + 1) + " normals 'N', not " + std::to_string(normals.size()));
    for (Vec3& n : normals) {
      if (!finitePoint(n) || !(dot(n, n) > 0.0f)) params.fail("curve: a ribbon's normal is zero or not finite");
      n = normalize(n);
    }
  }
  // Otherwise pbrt-v4 ignores the normals, as they are here (the parameter was read: no warning of its own).

  curve.vertices.reserve(shape.segments * kCurveControlPoints);
  size_t first = 0;  // the segment's first control point in `points`
  for (size_t s = 0; s < shape.segments; ++s) {
    std::array<Vec3, 4> bezier;
    if (!shape.bspline && shape.degree == 3) {
      bezier = {points[first], points[first + 1], points[first + 2], points[first + 3]};
    } else if (!shape.bspline) {
      bezier = elevateQuadraticBezierToCubic(&points[first]);
    } else if (shape.degree == 2) {
      const std::array<Vec3, 3> quadratic = quadraticBSplineToBezier(&points[first]);
      bezier = elevateQuadraticBezierToCubic(quadratic.data());
    } else {
      bezier = cubicBSplineToBezier(&points[first]);
    }
    first += shape.bspline ? 1 : size_t(shape.degree);
    // pbrt's width is linear in u over each segment, from the curve's width at its start to that at its end: as
    // cubic Bézier radii, the same line's values at thirds.
    const float u0 = float(s) / float(shape.segments), u1 = float(s + 1) / float(shape.segments);
    for (uint32_t i = 0; i < kCurveControlPoints; ++i) {
      const float t = float(i) / 3.0f, u = u0 + (u1 - u0) * t;
      const float radius = 0.5f * (width0 + (width1 - width0) * u);
      curve.vertices.push_back({bezier[i].x, bezier[i].y, bezier[i].z, radius});
      if (curve.type == CurveType::Ribbon) curve.normals.push_back(lerpPoints(t, normals[s], normals[s + 1]));
    }
  }
  return curve;
}

}  // namespace candela
