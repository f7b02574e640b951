#pragma once
// The bilateral filter's weights, shared by the CPU filter (bilateral.cpp) and its CUDA version, which sum the
// same taps in the same order.
#include "core/math.h"
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

// The weight of the tap at offset (dx, dy) with colour (qr, qg, qb) for the centre colour (pr, pg, pb).
CANDELA_FN float bilateralWeight(int dx, int dy, float pr, float pg, float pb, float qr, float qg, float qb,
                                 BilateralScales s) {
  const float r = qr - pr, g = qg - pg, b = qb - pb;
  return fastExpNonPositive(-float(dx * dx + dy * dy) * s.spatial - (r * r + g * g + b * b) * s.range);
}

}  // namespace candela
