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

// The largest value the filters work with: larger ones (finite, but absurd for radiance) are clamped to it, so that
// the squares of luminances and the sums of weighted taps stay finite and finite input never turns into NaN.
constexpr float kMaxFilteredValue = 1e18f;

// What the a-trous filter smooths at a pixel of mean radiance `color`, of which `emission` is seen emitted: the
// reflected rest, divided by the albedo. Emitted light is no lighting of the surface; divided by an emitter's
// albedo (often zero) and multiplied back by its neighbours' it would spread the emitter over them.
CANDELA_FN Vec3 demodulate(Vec3 color, Vec3 emission, Vec3 albedo) {
  auto channel = [](float c, float e, float a) {
    const float reflected = c - e > 0.0f ? c - e : 0.0f;  // rounding can leave it slightly negative
    return fminf(reflected / demodulationFactor(a), kMaxFilteredValue);
  };
  return {channel(color.x, emission.x, albedo.x), channel(color.y, emission.y, albedo.y),
          channel(color.z, emission.z, albedo.z)};
}

// The emission as the filter smooths it, in passes of its own: not demodulated (an emitter's albedo says nothing
// about its light), clamped like the rest. Its noise is at edges: pixels that straddle an emitter's edge see it with
// some samples and miss it with others.
CANDELA_FN Vec3 filterableEmission(Vec3 e) {
  return {fminf(e.x, kMaxFilteredValue), fminf(e.y, kMaxFilteredValue), fminf(e.z, kMaxFilteredValue)};
}

// The filtered pixel (reflected and emitted light), mixed with the raw one by the estimate of the mix's squared
// error: the filtered value is taken as noise-free but biased (a shadow or highlight smoothed, an emitter's edge
// spread), the raw one as unbiased with the variance of its mean luminance. The bias^2 is estimated as
// (difference of their luminances)^2 - variance; the mix that minimises bias^2 (1 - t)^2 + variance t^2 takes the
// raw value with weight t = bias^2 / (bias^2 + variance). So where a pixel has converged, or the filter moved it by
// more than its noise explains, the raw value stays; where it is noisy, the filtered one. Where the variance is not
// known (one sample), the filtered value is taken.
CANDELA_FN Vec3 blendWithRaw(Vec3 raw, Vec3 filtered, float variance) {
  if (variance < 0.0f) return filtered;
  const float d = fminf(fabsf(luminance(filtered) - luminance(raw)), kMaxFilteredValue);
  const float bias2 = d * d > variance ? d * d - variance : 0.0f;
  const float total = bias2 + variance;
  const float rawWeight = total > 0.0f ? bias2 / total : 0.0f;
  return filtered + (raw - filtered) * rawWeight;
}

// The neighbourhood over which stratifiedVariance pools the two estimates: (2 r + 1)^2 pixels.
constexpr int kStratificationRadius = 2;

// The variance of pixel (x, y)'s mean luminance for the mix with the raw pixel: its sample-variance bound
// (varianceAt, meanLuminanceVariance), scaled down by the ratio of the halves' estimate (halvesAt, halvesVariance,
// on the same scale) to it, both summed over the pixel's neighbourhood. The sample variance over the count is the
// variance of the mean for independent samples, but overstates it for stratified ones (Sobol), whose mean
// converges faster: at 64 samples the filter then trusted its blur too much and was worse than the raw image on
// the Cornell box (docs/denoising.md). The halves' estimate is unbiased either way but has one degree of freedom,
// so it only sets the ratio, over 25 pixels; the bound keeps each pixel's own structure. Never scaled up: for
// independent samples the ratio is 1 up to noise.
template <class VarianceAt, class HalvesAt>
CANDELA_HD float stratifiedVariance(const VarianceAt& varianceAt, const HalvesAt& halvesAt, int w, int h, int x,
                                    int y) {
  const float own = varianceAt(x, y);
  if (own < 0.0f) return own;
  float variances = 0.0f, halves = 0.0f;
  for (int dy = -kStratificationRadius; dy <= kStratificationRadius; ++dy) {
    if (y + dy < 0 || y + dy >= h) continue;
    for (int dx = -kStratificationRadius; dx <= kStratificationRadius; ++dx) {
      if (x + dx < 0 || x + dx >= w) continue;
      const float v = varianceAt(x + dx, y + dy), hv = halvesAt(x + dx, y + dy);
      if (v < 0.0f || hv < 0.0f) continue;
      variances = fminf(variances + v, 3.0e38f);
      halves = fminf(halves + hv, 3.0e38f);
    }
  }
  return variances > halves ? own * (halves / variances) : own;
}

// The variance blendWithRaw takes for pixel (x, y): its own (varianceAt(x, y)), or the median of its 3x3
// neighbourhood's inside the image where that is larger. A pixel whose few samples happened to agree (all black,
// say) has a variance near zero and would keep its raw value, a speck in the filtered image; its neighbours'
// median says how noisy such pixels are. A median rather than a mean, so that the large variance of the pixels
// along an edge (an emitter's, a shadow's) does not spread to the pixels beside it.
template <class VarianceAt>
CANDELA_HD float blendVariance(const VarianceAt& varianceAt, int w, int h, int x, int y) {
  const float own = varianceAt(x, y);
  if (own < 0.0f) return own;
  float v[9];
  int n = 0;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx)
      if (x + dx >= 0 && x + dx < w && y + dy >= 0 && y + dy < h) v[n++] = varianceAt(x + dx, y + dy);
  for (int i = 1; i < n; ++i) {  // insertion sort of at most nine
    const float t = v[i];
    int j = i - 1;
    for (; j >= 0 && v[j] > t; --j) v[j + 1] = v[j];
    v[j + 1] = t;
  }
  const float median = v[n / 2];
  return median > own ? median : own;
}

// The inverse of demodulate for the filtered reflected light.
CANDELA_FN Vec3 remodulate(Vec3 filtered, Vec3 albedo) {
  return {filtered.x * demodulationFactor(albedo.x), filtered.y * demodulationFactor(albedo.y),
          filtered.z * demodulationFactor(albedo.z)};
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

// The parts of a tap's weight that come from the guides (normal and depth), which signals filtered with the same
// guides share.
struct AtrousGuideTerms {
  float normal, depth;
};

// The guide terms of the tap (dx, dy) in [-2, 2]^2 of a pass.
CANDELA_FN AtrousGuideTerms atrousGuideTerms(int dx, int dy, const AtrousPassConstants& k, const AtrousCentre& p,
                                             float qnx, float qny, float qnz, float qz) {
  const float ox = float(dx * k.step), oy = float(dy * k.step);
  const float nx = qnx - p.nx, ny = qny - p.ny, nz = qnz - p.nz;
  const float expected = fabsf(p.gx * ox + p.gy * oy) + kAtrousDepthFloor * p.z * (fabsf(ox) + fabsf(oy));
  return {(nx * nx + ny * ny + nz * nz) * k.normalScale, fabsf(qz - p.z) / (k.depthSigma * expected + 1e-30f)};
}

// The weight of a tap whose kernel weight is b3Weight(dx) * b3Weight(dy), from the luminances of the centre and the
// tap and the guide terms.
CANDELA_FN float atrousWeight(float kernelWeight, float centreLuminance, float inverseColorWidth, float qLuminance,
                              AtrousGuideTerms guides) {
  const float colorTerm = fabsf(qLuminance - centreLuminance) * inverseColorWidth;
  return kernelWeight * fastExpNonPositive(-(colorTerm + guides.normal + guides.depth));
}

// The weight of the tap (dx, dy) in [-2, 2]^2 of a pass, whose kernel weight is b3Weight(dx) * b3Weight(dy).
CANDELA_FN float atrousWeight(int dx, int dy, float kernelWeight, const AtrousPassConstants& k, AtrousCentre p,
                              float qLuminance, float qnx, float qny, float qnz, float qz) {
  return atrousWeight(kernelWeight, p.luminance, p.inverseColorWidth, qLuminance,
                      atrousGuideTerms(dx, dy, k, p, qnx, qny, qnz, qz));
}

CANDELA_FN AtrousPassConstants atrousPassConstants(const AtrousParams& params, int pass) {
  return {1 << pass, 1.0f / (params.normalSigma * params.normalSigma), params.depthSigma};
}

}  // namespace candela
