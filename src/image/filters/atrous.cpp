#include "image/filters/atrous.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <stdexcept>
#include <string>

#include "image/filters/atrous_kernel.h"
#include "image/filters/planes.h"

namespace candela {

namespace {

struct GuidePlanes {
  std::vector<float> nx, ny, nz, z, gx, gy;
  explicit GuidePlanes(size_t n) : nx(n), ny(n), nz(n), z(n), gx(n), gy(n) {}
};

GuidePlanes makeGuides(const AovImages& aovs) {
  const int w = int(aovs.width()), h = int(aovs.height());
  GuidePlanes g(aovs.depth.size());
  auto depthAt = [&](int x, int y) {
    return x < 0 || y < 0 || x >= w || y >= h ? 0.0f : aovs.depth[size_t(y) * w + x];
  };
  tbb::parallel_for(0, h, [&](int y) {
    for (int x = 0; x < w; ++x) {
      const size_t i = size_t(y) * w + x;
      const Vec3 n = unitOrZero(aovs.normal.pixels[i]);
      g.nx[i] = n.x;
      g.ny[i] = n.y;
      g.nz[i] = n.z;
      g.z[i] = aovs.depth[i];
      g.gx[i] = depthSlope(depthAt(x - 1, y), g.z[i], depthAt(x + 1, y));
      g.gy[i] = depthSlope(depthAt(x, y - 1), g.z[i], depthAt(x, y + 1));
    }
  });
  return g;
}

float meanLuminance(const RgbPlanes& c) {
  const size_t n = c.r.size();
  double sum = tbb::parallel_reduce(
      tbb::blocked_range<size_t>(0, n), 0.0,
      [&](const tbb::blocked_range<size_t>& range, double partial) {
        for (size_t i = range.begin(); i < range.end(); ++i) partial += luminance(c.get(i));
        return partial;
      },
      [](double a, double b) { return a + b; });
  return n > 0 ? float(sum / double(n)) : 0.0f;
}

constexpr int kSpan = 256;

struct CentreRow {
  const float *lum, *inverseWidth, *nx, *ny, *nz, *z, *gx, *gy;
};
struct TapRow {
  const float *r, *g, *b, *nx, *ny, *nz, *z;
};

// Adds the tap (dx, dy) to the sums of pixels [x0, x1) of a row. Compiled for AVX2 as well as the baseline
// instruction set (chosen at run time); no FMA, so every build computes the same sums as the CUDA version.
__attribute__((target_clones("avx512f", "avx2", "default"))) void accumulateTap(const CentreRow& c, const TapRow& t,
                                                                       RowSums& sums, int x0, int x1, int dx,
                                                                       int dy, AtrousPassConstants k) {
  const float kernelWeight = b3Weight(dx) * b3Weight(dy);
  const int ox = dx * k.step;
  const float *pl = c.lum, *pw = c.inverseWidth, *pnx = c.nx, *pny = c.ny, *pnz = c.nz, *pz = c.z, *pgx = c.gx,
              *pgy = c.gy;
  const float *qr = t.r, *qg = t.g, *qb = t.b, *qnx = t.nx, *qny = t.ny, *qnz = t.nz, *qz = t.z;
  float *sr = sums.r.data(), *sg = sums.g.data(), *sb = sums.b.data(), *sw = sums.weight.data();
#pragma GCC ivdep  // the sums and the planes never overlap
  for (int x = x0; x < x1; ++x) {
    const int q = x + ox;
    const AtrousCentre p{pl[x], pw[x], pnx[x], pny[x], pnz[x], pz[x], pgx[x], pgy[x]};
    const float weight =
        atrousWeight(dx, dy, kernelWeight, k, p, qr[q], qg[q], qb[q], qnx[q], qny[q], qnz[q], qz[q]);
    sr[x] += qr[q] * weight;
    sg[x] += qg[q] * weight;
    sb[x] += qb[q] * weight;
    sw[x] += weight;
  }
}

// One pass, tap by tap over whole rows so that the inner loop vectorises over contiguous pixels; every pixel
// still sums its taps in the (dy, dx) order of the CUDA version.
void atrousPass(const RgbPlanes& in, RgbPlanes& out, const GuidePlanes& g, const AtrousPassConstants& k,
                float colorSigma, float mean, std::vector<float>& lum, std::vector<float>& inverseWidth) {
  const int w = int(in.width), h = int(in.height);
  tbb::parallel_for(size_t(0), lum.size(), [&](size_t i) { lum[i] = luminance(in.get(i)); });
  tbb::parallel_for(0, h, [&](int y) {
    for (int x = 0; x < w; ++x)
      inverseWidth[size_t(y) * w + x] =
          atrousInverseColorWidth(localLuminanceVariance(lum.data(), w, h, x, y), colorSigma, mean);
  });
  tbb::parallel_for(tbb::blocked_range<int>(0, h), [&](const tbb::blocked_range<int>& rows) {
    RowSums sums(in.width);
    for (int y = rows.begin(); y < rows.end(); ++y) {
      sums.clear();
      const size_t row = size_t(y) * w;
      const CentreRow centre{&lum[row], &inverseWidth[row], &g.nx[row], &g.ny[row], &g.nz[row],
                             &g.z[row], &g.gx[row], &g.gy[row]};
      // In spans short enough that the rows a span reads stay in the L1 cache over its 25 taps.
      for (int start = 0; start < w; start += kSpan) {
        const int end = std::min(w, start + kSpan);
        for (int dy = -2; dy <= 2; ++dy) {
          const int qy = y + dy * k.step;
          if (qy < 0 || qy >= h) continue;
          const size_t tapRow = size_t(qy) * w;
          const TapRow tap{&in.r[tapRow], &in.g[tapRow], &in.b[tapRow], &g.nx[tapRow],
                           &g.ny[tapRow], &g.nz[tapRow], &g.z[tapRow]};
          for (int dx = -2; dx <= 2; ++dx) {
            const int ox = dx * k.step;
            accumulateTap(centre, tap, sums, std::max(start, -ox), std::min(end, w - ox), dx, dy, k);
          }
        }
      }
      // The centre tap's weight is b3(0)^2 > 0: the sum of weights is never zero.
      for (int x = 0; x < w; ++x) out.set(row + x, Vec3{sums.r[x], sums.g[x], sums.b[x]} / sums.weight[x]);
    }
  });
}

}  // namespace

void validateAtrousParams(const AtrousParams& params) {
  if (params.passes < 0 || params.passes > kMaxAtrousPasses)
    throw std::invalid_argument("a-trous passes must lie in [0, " + std::to_string(kMaxAtrousPasses) + "]");
  if (!(params.colorSigma > 0.0f) || !(params.normalSigma > 0.0f) || !(params.depthSigma > 0.0f))
    throw std::invalid_argument("a-trous sigmas must be positive");
}

void validateAtrousInput(const Image& color, const AovImages& aovs, const AtrousParams& params) {
  validateAtrousParams(params);
  const uint32_t w = color.width, h = color.height;
  if (aovs.albedo.width != w || aovs.albedo.height != h || aovs.normal.width != w || aovs.normal.height != h ||
      aovs.depth.size() != size_t(w) * h)
    throw std::invalid_argument("the a-trous filter's AOVs differ in size from the image");
}

Image atrousDenoise(const Image& color, const AovImages& aovs, const AtrousParams& params) {
  validateAtrousInput(color, aovs, params);
  const GuidePlanes guides = makeGuides(aovs);
  RgbPlanes a(color.width, color.height), b(color.width, color.height);
  tbb::parallel_for(size_t(0), color.pixels.size(), [&](size_t i) {
    const Vec3 c = color.pixels[i], albedo = aovs.albedo.pixels[i];
    a.set(i, {c.x / demodulationFactor(albedo.x), c.y / demodulationFactor(albedo.y),
              c.z / demodulationFactor(albedo.z)});
  });
  const float mean = meanLuminance(a);
  std::vector<float> lum(a.r.size()), inverseWidth(a.r.size());
  for (int pass = 0; pass < params.passes; ++pass) {
    atrousPass(a, b, guides, atrousPassConstants(params, pass), params.colorSigma, mean, lum, inverseWidth);
    std::swap(a, b);
  }
  Image result(color.width, color.height);
  tbb::parallel_for(size_t(0), result.pixels.size(), [&](size_t i) {
    const Vec3 albedo = aovs.albedo.pixels[i], c = a.get(i);
    result.pixels[i] = {c.x * demodulationFactor(albedo.x), c.y * demodulationFactor(albedo.y),
                        c.z * demodulationFactor(albedo.z)};
  });
  return result;
}

}  // namespace candela
