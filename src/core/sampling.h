#pragma once
#include "core/math.h"

namespace candela {

// Concentric mapping of the unit square to the unit disk (Shirley and Chiu 1997).
CANDELA_FN Vec2 sampleUniformDiskConcentric(Vec2 u) {
  float ox = 2.0f * u.x - 1.0f, oy = 2.0f * u.y - 1.0f;
  if (ox == 0.0f && oy == 0.0f) return {0.0f, 0.0f};
  float r, theta;
  if (fabsf(ox) > fabsf(oy)) {
    r = ox;
    theta = 0.25f * kPi * (oy / ox);
  } else {
    r = oy;
    theta = 0.5f * kPi - 0.25f * kPi * (ox / oy);
  }
  return {r * cosf(theta), r * sinf(theta)};
}

// Cosine-weighted direction about +z (Malley's method).
CANDELA_FN Vec3 sampleCosineHemisphere(Vec2 u) {
  Vec2 d = sampleUniformDiskConcentric(u);
  float z = sqrtf(fmaxf(0.0f, 1.0f - d.x * d.x - d.y * d.y));
  return {d.x, d.y, z};
}
CANDELA_FN float cosineHemispherePdf(float cosTheta) { return cosTheta > 0.0f ? cosTheta * kInvPi : 0.0f; }

CANDELA_FN Vec3 sampleUniformSphere(Vec2 u) {
  float z = 1.0f - 2.0f * u.x;
  float r = sqrtf(fmaxf(0.0f, 1.0f - z * z));
  float phi = 2.0f * kPi * u.y;
  return {r * cosf(phi), r * sinf(phi), z};
}
CANDELA_FN float uniformSpherePdf() { return 1.0f / (4.0f * kPi); }

// Barycentrics (b0, b1) of a uniformly distributed point on a triangle (Heitz 2019, low-distortion map).
CANDELA_FN Vec2 sampleUniformTriangle(Vec2 u) {
  float b0, b1;
  if (u.x < u.y) {
    b0 = u.x / 2.0f;
    b1 = u.y - b0;
  } else {
    b1 = u.y / 2.0f;
    b0 = u.x - b1;
  }
  return {b0, b1};
}

// Veach's power heuristic with beta = 2, for nf samples of f against ng samples of g (here always 1 and 1).
CANDELA_FN float powerHeuristic(float pdfF, float pdfG) {
  if (pdfF >= kInf) return 1.0f;  // a delta distribution always wins
  float f2 = pdfF * pdfF, g2 = pdfG * pdfG;
  if (f2 + g2 == 0.0f) return 0.0f;
  return f2 / (f2 + g2);
}

// The bucket i in [lo, hi) of a sorted cumulative table with cdf[i] <= u < cdf[i + 1], given cdf[lo] <= u < cdf[hi].
CANDELA_FN int searchInterval(const float* cdf, int lo, int hi, float u) {
  while (hi - lo > 1) {
    int mid = (lo + hi) / 2;
    if (cdf[mid] <= u)
      lo = mid;
    else
      hi = mid;
  }
  return lo;
}

// Finds the bucket of a sorted cumulative table (cdf[0] = 0, cdf[n] = 1) that holds u.
CANDELA_FN int findInterval(const float* cdf, int n, float u) { return searchInterval(cdf, 0, n, u); }

// findInterval(cdf, n, u) for 0 <= u, searched only between the buckets a guide table names (Chen and Asau's
// guide table, 1974): guide[g] is the bucket of g / n for g < n, guide[n] = n - 1, so that u's search starts
// between guide[g] and guide[g + 1] + 1 for g = floor(u * n), one or two buckets where the table is smooth instead
// of log2(n). Where rounding leaves u outside that bracket, the bracket widens to the whole table: the bucket is
// always the one findInterval finds.
CANDELA_FN int findGuidedInterval(const float* cdf, const uint32_t* guide, int n, float u) {
  const float cell = u * float(n);
  const int g = cell > 0.0f ? (cell < float(n - 1) ? int(cell) : n - 1) : 0;
  int lo = int(guide[g]), hi = int(guide[g + 1]) + 1;
  if (!(cdf[lo] <= u)) lo = 0;
  if (!(u < cdf[hi])) hi = n;
  return searchInterval(cdf, lo, hi, u);
}

}  // namespace candela
