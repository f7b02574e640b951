#pragma once
// The bilateral filter's weights, shared by the CPU filter (bilateral.cpp) and its CUDA version, which sum the
// same taps in the same order.
#include "core/math.h"
#include "image/filters/atrous_kernel.h"
#include "image/filters/bilateral.h"
#include "image/filters/fast_exp.h"

namespace candela {

struct BilateralScales {
  float spatial;  // 1 / (2 spatialSigma^2)
  float range;    // 1 / (2 rangeSigma^2)
};

inline BilateralScales bilateralScales(const BilateralParams& params) {
  return {1.0f / (2.0f * params.spatialSigma * params.spatialSigma),
          1.0f / (2.0f * params.rangeSigma * params.rangeSigma)};
}

// A pixel's colour as the filter sums it: clamped to +-kMaxFilteredValue like the a-trous filter's values, so that
// the sums of weighted taps stay finite.
CANDELA_FN Vec3 bilateralInput(Vec3 color) {
  auto channel = [](float c) { return fmaxf(fminf(c, kMaxFilteredValue), -kMaxFilteredValue); };
  return {channel(color.x), channel(color.y), channel(color.z)};
}

// A pixel of mean radiance `color` of which `emission` is seen emitted: the rest, which the filter smooths.
CANDELA_FN Vec3 bilateralReflected(Vec3 color, Vec3 emission) {
  auto channel = [](float c, float e) { return c - e > 0.0f ? fminf(c - e, kMaxFilteredValue) : 0.0f; };
  return {channel(color.x, emission.x), channel(color.y, emission.y), channel(color.z, emission.z)};
}

// The weight of the tap at offset (dx, dy) with colour (qr, qg, qb) for the centre colour (pr, pg, pb).
CANDELA_FN float bilateralWeight(int dx, int dy, float pr, float pg, float pb, float qr, float qg, float qb,
                                 BilateralScales s) {
  const float r = qr - pr, g = qg - pg, b = qb - pb;
  return fastExpNonPositive(-float(dx * dx + dy * dy) * s.spatial - (r * r + g * g + b * b) * s.range);
}

}  // namespace candela
