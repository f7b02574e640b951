#pragma once
// pbrt-v4's `curve` shape (Curve::Create) as candela's curves (kernel/curve.h): cubic Bézier segments with a radius
// at each control point. Bézier curves of degree 2 are raised to degree 3 and uniform b-splines converted segment by
// segment, with pbrt-v4's formulas (util/splines.h); widths run linearly from width0 to width1 over the whole curve,
// as pbrt-v4 interpolates them. pbrt's `splitdepth` only splits a curve for its own intersector: Embree and OptiX
// intersect the whole segment.
#include <array>
#include <cstddef>
#include <vector>

#include "core/math.h"
#include "kernel/curve.h"
#include "scene/loaders/pbrt/pbrt_parameters.h"

namespace candela {

// One curve shape's segments, in its object space.
struct PbrtCurve {
  CurveType type = CurveType::Flat;
  std::vector<Vec4> vertices;  // 4 per segment: xyz and the radius (half pbrt's width)
  std::vector<Vec3> normals;   // ribbons only: one per vertex
};

// The segments `params` describe. Refuses, with LoadError naming the directive's file and line: a basis other than
// bezier or bspline, a degree other than 2 or 3, a control point count the basis and degree cannot take, an unknown
// type, widths that are not positive and finite, ribbons without one non-zero normal per segment end.
PbrtCurve makePbrtCurve(const PbrtParameters& params);

// The bytes makePbrtCurve's result and its place in the scene's arrays take for the parameters' point count, counted
// before building (the load's memory budget); 0 where the parameters will be refused.
size_t pbrtCurveBytes(const PbrtParameters& params);

// pbrt-v4's conversions to cubic Bézier control points (util/splines.h).
std::array<Vec3, 4> elevateQuadraticBezierToCubic(const Vec3 p[3]);
std::array<Vec3, 3> quadraticBSplineToBezier(const Vec3 p[3]);
std::array<Vec3, 4> cubicBSplineToBezier(const Vec3 p[4]);

}  // namespace candela
