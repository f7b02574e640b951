#pragma once
// The a-trous filter's per-pixel and per-tap arithmetic, shared by the CPU filter (atrous.cpp) and its CUDA
// version, which sum the same taps in the same order.
#include "core/math.h"
#include "image/filters/atrous.h"
#include "image/filters/fast_exp.h"

namespace candela {

// Albedo channels below this are not divided out: the lighting of near-black surfaces stays as it is.
constexpr float kMinDemodulationAlbedo = 0.01f;
// The depth difference every tap may have regardless of the gradient, relative to depth and tap distance.
constexpr float kAtrousDepthFloor = 1e-3f;

CANDELA_FN float demodulationFactor(float albedo) {
  return albedo > kMinDemodulationAlbedo ? albedo : kMinDemodulationAlbedo;
}

CANDELA_FN Vec3 unitOrZero(Vec3 n) {
  const float len = sqrtf(dot(n, n));
  return len > 0.0f ? n / len : Vec3{0, 0, 0};
}

// The B3 spline (1, 4, 6, 4, 1) / 16 at i in [-2, 2].
CANDELA_FN float b3Weight(int i) { return i == 0 ? 0.375f : (i == 1 || i == -1) ? 0.25f : 0.0625f; }

// The depth change per pixel at a pixel whose neighbours on one axis have depths `before` and `after` (zero
// where a neighbour is outside the image or missed everything): the smaller one-sided difference, so that a
// pixel at an object's silhouette takes the slope of its own surface.
CANDELA_FN float depthSlope(float before, float centre, float after) {
  if (centre == 0.0f) return 0.0f;
  const float back = before > 0.0f ? centre - before : 3.0e38f, ahead = after > 0.0f ? after - centre : 3.0e38f;
  const float slope = fabsf(back) < fabsf(ahead) ? back : ahead;
  return fabsf(slope) < 3.0e38f ? slope : 0.0f;
}

// The variance of the luminance around (x, y): over its 3x3 neighbourhood inside the image, weighted by the
// binomial kernel (1, 2, 1) per axis. The colour edge-stopping width scales with its square root (SVGF): where
// the image is noisy (a firefly, say) neighbours are taken in, where it is smooth differences count.
CANDELA_FN float localLuminanceVariance(const float* luminanceOf, int w, int h, int x, int y) {
  float sum = 0.0f, sumSquares = 0.0f, weights = 0.0f;
  for (int dy = -1; dy <= 1; ++dy) {
    if (y + dy < 0 || y + dy >= h) continue;
    for (int dx = -1; dx <= 1; ++dx) {
      if (x + dx < 0 || x + dx >= w) continue;
      const float weight = float((dx == 0 ? 2 : 1) * (dy == 0 ? 2 : 1));
      const float l = luminanceOf[size_t(y + dy) * w + x + dx];
      sum += weight * l;
      sumSquares += weight * l * l;
      weights += weight;
    }
  }
  const float mean = sum / weights;
  const float variance = sumSquares / weights - mean * mean;
  return variance > 0.0f ? variance : 0.0f;
}

// localLuminanceVariance at a pixel x whose whole neighbourhood lies inside the image, given the rows above, at and
// below it: the same operations in the same order (the weights sum to 16 exactly), without the bounds checks, so that a
// loop over a row's pixels vectorises.
CANDELA_FN float interiorLuminanceVariance(const float* above, const float* row, const float* below, int x) {
  float sum = 0.0f, sumSquares = 0.0f;
  const float* rows[3] = {above, row, below};
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const float weight = float((dx == 0 ? 2 : 1) * (dy == 0 ? 2 : 1));
      const float l = rows[dy + 1][x + dx];
      sum += weight * l;
      sumSquares += weight * l * l;
    }
  const float mean = sum / 16.0f;
  const float variance = sumSquares / 16.0f - mean * mean;
  return variance > 0.0f ? variance : 0.0f;
}

// Luminance differences count in units of this: colorSigma standard deviations of the local noise, plus a floor
// of 1% of the image's mean demodulated luminance so that flat regions still smooth a little.
CANDELA_FN float atrousInverseColorWidth(float variance, float colorSigma, float meanLuminance) {
  const float floor = 1e-2f * (meanLuminance > 0.0f ? meanLuminance : 1.0f);
  return 1.0f / (colorSigma * sqrtf(variance) + floor);
}

struct AtrousPassConstants {
  int step;           // pixels between taps: 2^pass
  float normalScale;  // 1 / sigma_n^2
  float depthSigma;
};

// The guides of the pixel being filtered.
struct AtrousCentre {
  float luminance;          // of the demodulated colour
  float inverseColorWidth;  // atrousInverseColorWidth at this pixel in this pass
  float nx, ny, nz;         // unit normal, or zero
  float z, gx, gy;          // depth and its slope per pixel along x and y
};

// The weight of the tap (dx, dy) in [-2, 2]^2 of a pass, whose kernel weight is b3Weight(dx) * b3Weight(dy).
CANDELA_FN float atrousWeight(int dx, int dy, float kernelWeight, const AtrousPassConstants& k, AtrousCentre p,
                              float qLuminance, float qnx, float qny, float qnz, float qz) {
  const float ox = float(dx * k.step), oy = float(dy * k.step);
  const float colorTerm = fabsf(qLuminance - p.luminance) * p.inverseColorWidth;
  const float nx = qnx - p.nx, ny = qny - p.ny, nz = qnz - p.nz;
  const float expected = fabsf(p.gx * ox + p.gy * oy) + kAtrousDepthFloor * p.z * (fabsf(ox) + fabsf(oy));
  const float depthTerm = fabsf(qz - p.z) / (k.depthSigma * expected + 1e-30f);
  const float exponent = colorTerm + (nx * nx + ny * ny + nz * nz) * k.normalScale + depthTerm;
  return kernelWeight * fastExpNonPositive(-exponent);
}

CANDELA_FN AtrousPassConstants atrousPassConstants(const AtrousParams& params, int pass) {
  return {1 << pass, 1.0f / (params.normalSigma * params.normalSigma), params.depthSigma};
}

}  // namespace candela
