#pragma once
// Hits on curves that Embree reports and a curve does not have (kernel/curve.h). Both run on every query of the
// geometry they are set on, intersect and occluded; single-ray queries with a PassThroughContext.
//
// A tube (CurveType::Cylinder) is one-sided: a ray that meets its wall from inside, which only a ray starting on
// the tube can, passes, so that light a hair fibre transmits (its BSDF accounts for both walls) and shadow rays
// leave it. A flat curve faces every ray, so a ray leaving one would meet it again within its width: as pbrt-v4
// offsets a ray leaving a curve by the curve's width, hits on a flat curve closer to the ray's origin than its
// width are passed.
#include "backends/cpu/embree.h"

namespace candela {

void rejectCurveInsideHits(const RTCFilterFunctionNArguments* args);
void rejectFlatCurveSelfHits(const RTCFilterFunctionNArguments* args);

}  // namespace candela
