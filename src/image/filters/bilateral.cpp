#include "image/filters/bilateral.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <stdexcept>
#include <string>

#include "image/filters/bilateral_kernel.h"
#include "image/filters/planes.h"

namespace candela {

void validateBilateralParams(const BilateralParams& params) {
  if (params.radius < 0 || params.radius > kMaxBilateralRadius)
    throw std::invalid_argument("bilateral radius must lie in [0, " + std::to_string(kMaxBilateralRadius) + "]");
  if (!(params.spatialSigma > 0.0f) || !(params.rangeSigma > 0.0f))
    throw std::invalid_argument("bilateral sigmas must be positive");
}

namespace {

struct Planes {
  const float *r, *g, *b;
};

// Adds the tap (dx, dy) to the sums of pixels [x0, x1) of a row; compiled for AVX2 as well as the baseline
// instruction set (chosen at run time), without FMA, so every build computes the CUDA version's sums.
__attribute__((target_clones("avx512f", "avx2", "default"))) void accumulateTap(Planes centre, Planes tap,
                                                                                RowSums& sums, int x0, int x1, int dx,
                                                                                int dy, BilateralScales scales) {
  const float *pr = centre.r, *pg = centre.g, *pb = centre.b, *qr = tap.r, *qg = tap.g, *qb = tap.b;
  float *sr = sums.r.data(), *sg = sums.g.data(), *sb = sums.b.data(), *sw = sums.weight.data();
#pragma GCC ivdep  // the sums and the planes never overlap
  for (int x = x0; x < x1; ++x) {
    const int q = x + dx;
    const float weight = bilateralWeight(dx, dy, pr[x], pg[x], pb[x], qr[q], qg[q], qb[q], scales);
    sr[x] += qr[q] * weight;
    sg[x] += qg[q] * weight;
    sb[x] += qb[q] * weight;
    sw[x] += weight;
  }
}

}  // namespace

// Tap by tap over whole rows rather than pixel by pixel, so that the inner loop runs over contiguous pixels and
// vectorises; every pixel still sums its taps in the (dy, dx) order of the CUDA and GLSL versions.
Image bilateralFilter(const Image& input, const BilateralParams& params) {
  validateBilateralParams(params);
  const BilateralScales scales = bilateralScales(params);
  const int r = params.radius, w = int(input.width), h = int(input.height);
  const size_t pixels = input.pixels.size();
  PlaneStack planes(3, pixels);
  const RgbPlanes in{planes[0], planes[1], planes[2]};
  for (size_t i = 0; i < pixels; ++i) in.set(i, bilateralInput(input.pixels[i]));
  Image output(input.width, input.height);
  tbb::parallel_for(tbb::blocked_range<int>(0, h), [&](const tbb::blocked_range<int>& rows) {
    RowSums sums(input.width);
    for (int y = rows.begin(); y < rows.end(); ++y) {
      sums.clear();
      const size_t row = size_t(y) * w;
      const Planes centre{&in.r[row], &in.g[row], &in.b[row]};
      for (int dy = -r; dy <= r; ++dy) {
        if (y + dy < 0 || y + dy >= h) continue;
        const size_t tapRow = size_t(y + dy) * w;
        const Planes tap{&in.r[tapRow], &in.g[tapRow], &in.b[tapRow]};
        for (int dx = -r; dx <= r; ++dx)
          accumulateTap(centre, tap, sums, std::max(0, -dx), std::min(w, w - dx), dx, dy, scales);
      }
      for (int x = 0; x < w; ++x) output.pixels[row + x] = Vec3{sums.r[x], sums.g[x], sums.b[x]} / sums.weight[x];
    }
  });
  return output;
}

Image bilateralFilter(const Image& input, const Image& emission, const BilateralParams& params) {
  if (emission.width != input.width || emission.height != input.height)
    throw std::invalid_argument("the bilateral filter's emission differs in size from the image");
  Image reflected(input.width, input.height);
  for (size_t i = 0; i < input.pixels.size(); ++i)
    reflected.pixels[i] = bilateralReflected(input.pixels[i], emission.pixels[i]);
  Image output = bilateralFilter(reflected, params);
  for (size_t i = 0; i < output.pixels.size(); ++i) output.pixels[i] += emission.pixels[i];
  return output;
}

}  // namespace candela
