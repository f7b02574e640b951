#include "image/filters/atrous.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "image/filters/atrous_kernel.h"
#include "image/filters/planes.h"

namespace candela {

namespace {

// The planes one call works on: the guides, then per signal its luminance, its colour widths and its colour in the
// two buffers the passes alternate between.
constexpr size_t kGuidePlanes = 6;
constexpr size_t kPlanesPerSignal = 8;
constexpr size_t kPlaneCount = kGuidePlanes + 2 * kPlanesPerSignal;
enum GuidePlane : size_t { kNx, kNy, kNz, kDepth, kSlopeX, kSlopeY };
enum SignalPlane : size_t { kLuminance, kInverseWidth, kColour };

// The workspace's planes by name.
struct Planes {
  PlaneStack& stack;
  const float* operator[](GuidePlane p) const { return stack[p]; }
  float* operator[](GuidePlane p) { return stack[p]; }
  float* of(int signal, SignalPlane p) { return stack[kGuidePlanes + kPlanesPerSignal * size_t(signal) + p]; }
  // A signal's colour in one of its two buffers.
  RgbPlanes colour(int signal, int buffer) {
    const size_t first = kGuidePlanes + kPlanesPerSignal * size_t(signal) + kColour + 3 * size_t(buffer);
    return {stack[first], stack[first + 1], stack[first + 2]};
  }
};

// depthSlope of n pixels, given the depths one pixel before and after each (zero outside the image).
void depthSlopes(const float* before, const float* centre, const float* after, float* slope, int n) {
  for (int i = 0; i < n; ++i) slope[i] = depthSlope(before[i], centre[i], after[i]);
}

void fillGuides(const AovImages& aovs, Planes& planes) {
  const int w = int(aovs.width()), h = int(aovs.height());
  const std::vector<float> zeros(size_t(w), 0.0f);
  tbb::parallel_for(0, h, [&](int y) {
    const size_t row = size_t(y) * w;
    float *nx = planes[kNx] + row, *ny = planes[kNy] + row, *nz = planes[kNz] + row, *z = planes[kDepth] + row;
    for (int x = 0; x < w; ++x) {
      const Vec3 n = unitOrZero(aovs.normal.pixels[row + x]);
      nx[x] = n.x;
      ny[x] = n.y;
      nz[x] = n.z;
    }
    std::copy_n(&aovs.depth[row], w, z);
    const float* depth = aovs.depth.data();
    float* slopeX = planes[kSlopeX] + row;
    slopeX[0] = depthSlope(0.0f, z[0], w > 1 ? z[1] : 0.0f);
    if (w > 2) depthSlopes(z, z + 1, z + 2, slopeX + 1, w - 2);
    if (w > 1) slopeX[w - 1] = depthSlope(z[w - 2], z[w - 1], 0.0f);
    depthSlopes(y > 0 ? depth + row - w : zeros.data(), z, y + 1 < h ? depth + row + w : zeros.data(),
                planes[kSlopeY] + row, w);
  });
}

float meanLuminance(const RgbPlanes& c, size_t n) {
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
  const float *r, *g, *b, *lum, *nx, *ny, *nz, *z;
};
// The second signal's planes beside a CentreRow and a TapRow, which hold the first's and the guides.
struct SecondCentreRow {
  const float *lum, *inverseWidth;
};
struct SecondTapRow {
  const float *r, *g, *b, *lum;
};

// Adds the tap (dx, dy) to the sums of pixels [x0, x1) of a row. Compiled for x86-64-v4 (AVX-512) and -v3 (AVX2, FMA)
// as well as the baseline instruction set, chosen at run time.
__attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default"))) void accumulateTap(
    const CentreRow& c, const TapRow& t, RowSums& sums, int x0, int x1, int dx, int dy, AtrousPassConstants k) {
  const float kernelWeight = b3Weight(dx) * b3Weight(dy);
  const int ox = dx * k.step;
  const float *pl = c.lum, *pw = c.inverseWidth, *pnx = c.nx, *pny = c.ny, *pnz = c.nz, *pz = c.z, *pgx = c.gx,
              *pgy = c.gy;
  const float *qr = t.r, *qg = t.g, *qb = t.b, *ql = t.lum, *qnx = t.nx, *qny = t.ny, *qnz = t.nz, *qz = t.z;
  float *sr = sums.r.data(), *sg = sums.g.data(), *sb = sums.b.data(), *sw = sums.weight.data();
#pragma GCC ivdep  // the sums and the planes never overlap
  for (int x = x0; x < x1; ++x) {
    const int q = x + ox;
    const AtrousCentre p{pl[x], pw[x], pnx[x], pny[x], pnz[x], pz[x], pgx[x], pgy[x]};
    const float weight = atrousWeight(dx, dy, kernelWeight, k, p, ql[q], qnx[q], qny[q], qnz[q], qz[q]);
    sr[x] += qr[q] * weight;
    sg[x] += qg[q] * weight;
    sb[x] += qb[q] * weight;
    sw[x] += weight;
  }
}

// accumulateTap for two signals at once: the guides are read and their terms computed once for both.
__attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default"))) void accumulateTapOfTwo(
    const CentreRow& c, const SecondCentreRow& c1, const TapRow& t, const SecondTapRow& t1, RowSums& sums,
    RowSums& sums1, int x0, int x1, int dx, int dy, AtrousPassConstants k) {
  const float kernelWeight = b3Weight(dx) * b3Weight(dy);
  const int ox = dx * k.step;
  const float *pl = c.lum, *pw = c.inverseWidth, *pnx = c.nx, *pny = c.ny, *pnz = c.nz, *pz = c.z, *pgx = c.gx,
              *pgy = c.gy, *pl1 = c1.lum, *pw1 = c1.inverseWidth;
  const float *qr = t.r, *qg = t.g, *qb = t.b, *ql = t.lum, *qnx = t.nx, *qny = t.ny, *qnz = t.nz, *qz = t.z;
  const float *qr1 = t1.r, *qg1 = t1.g, *qb1 = t1.b, *ql1 = t1.lum;
  float *sr = sums.r.data(), *sg = sums.g.data(), *sb = sums.b.data(), *sw = sums.weight.data();
  float *sr1 = sums1.r.data(), *sg1 = sums1.g.data(), *sb1 = sums1.b.data(), *sw1 = sums1.weight.data();
#pragma GCC ivdep  // the sums and the planes never overlap
  for (int x = x0; x < x1; ++x) {
    const int q = x + ox;
    const AtrousCentre p{pl[x], pw[x], pnx[x], pny[x], pnz[x], pz[x], pgx[x], pgy[x]};
    const AtrousGuideTerms guides = atrousGuideTerms(dx, dy, k, p, qnx[q], qny[q], qnz[q], qz[q]);
    const float weight = atrousWeight(kernelWeight, pl[x], pw[x], ql[q], guides);
    const float weight1 = atrousWeight(kernelWeight, pl1[x], pw1[x], ql1[q], guides);
    sr[x] += qr[q] * weight;
    sg[x] += qg[q] * weight;
    sb[x] += qb[q] * weight;
    sw[x] += weight;
    sr1[x] += qr1[q] * weight1;
    sg1[x] += qg1[q] * weight1;
    sb1[x] += qb1[q] * weight1;
    sw1[x] += weight1;
  }
}

// The centre tap differs from itself in nothing: atrousWeight's exponent is zero and the weight is the kernel's.
__attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default"))) void accumulateCentre(const TapRow& t,
                                                                                                    RowSums& sums,
                                                                                                    int x0, int x1) {
  constexpr float kWeight = 0.375f * 0.375f;
  const float *qr = t.r, *qg = t.g, *qb = t.b;
  float *sr = sums.r.data(), *sg = sums.g.data(), *sb = sums.b.data(), *sw = sums.weight.data();
#pragma GCC ivdep  // the sums and the planes never overlap
  for (int x = x0; x < x1; ++x) {
    sr[x] += qr[x] * kWeight;
    sg[x] += qg[x] * kWeight;
    sb[x] += qb[x] * kWeight;
    sw[x] += kWeight;
  }
}

// atrousInverseColorWidth of every pixel of row y. Pixels whose 3x3 neighbourhood lies inside the image take the
// bounds-free variance in a loop that vectorises.
__attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default"))) void inverseColorWidthRow(
    const float* lum, int w, int h, int y, float colorSigma, float mean, float* out) {
  auto edgePixel = [&](int x) {
    out[x] = atrousInverseColorWidth(localLuminanceVariance(lum, w, h, x, y), colorSigma, mean);
  };
  if (y == 0 || y + 1 >= h || w < 3) {
    for (int x = 0; x < w; ++x) edgePixel(x);
    return;
  }
  const float *above = lum + size_t(y - 1) * w, *row = lum + size_t(y) * w, *below = lum + size_t(y + 1) * w;
  edgePixel(0);
  for (int x = 1; x + 1 < w; ++x)
    out[x] = atrousInverseColorWidth(interiorLuminanceVariance(above, row, below, x), colorSigma, mean);
  edgePixel(w - 1);
}

// The columns [first, last) of a row outside which a signal is zero in every channel; first == last where all of
// the row is.
struct NonZeroColumns {
  int first = 0, last = 0;
};

NonZeroColumns nonZeroColumns(const RgbPlanes& c, size_t row, int w) {
  auto nonZero = [&](int x) { return c.r[row + x] != 0.0f || c.g[row + x] != 0.0f || c.b[row + x] != 0.0f; };
  int first = 0;
  while (first < w && !nonZero(first)) ++first;
  if (first == w) return {};
  int last = w;
  while (!nonZero(last - 1)) --last;
  return {first, last};
}

// The columns of row y where a pass may give a pixel other than zero: those with a tap in a non-zero column.
// Elsewhere every tap is zero, so the weighted mean is (exactly) zero: a signal that is zero in most pixels (the
// emission, where a few lights are seen) is filtered only around where it is not.
NonZeroColumns outputColumns(const std::vector<NonZeroColumns>& columns, int y, int w, int h, int step) {
  int first = w, last = 0;
  for (int dy = -2; dy <= 2; ++dy) {
    const int qy = y + dy * step;
    if (qy < 0 || qy >= h || columns[qy].first == columns[qy].last) continue;
    first = std::min(first, columns[qy].first - 2 * step);
    last = std::max(last, columns[qy].last + 2 * step);
  }
  first = std::max(first, 0);
  last = std::min(last, w);
  return first < last ? NonZeroColumns{first, last} : NonZeroColumns{};
}

// The weighted means of a row's sums in columns [cols.first, cols.last) into the row of `out` that starts at pixel
// `row`, zero in its other columns. The centre tap's weight is b3(0)^2 > 0: the sum of weights is never zero where
// taps were summed.
__attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default"))) void writeWeightedMeans(
    const RowSums& sums, NonZeroColumns cols, const RgbPlanes& out, size_t row, int w) {
  const float *sr = sums.r.data(), *sg = sums.g.data(), *sb = sums.b.data(), *sw = sums.weight.data();
  float *r = out.r + row, *g = out.g + row, *b = out.b + row;
  for (int x = 0; x < cols.first; ++x) r[x] = g[x] = b[x] = 0.0f;
#pragma GCC ivdep  // the sums and the planes never overlap
  for (int x = cols.first; x < cols.last; ++x) {
    const Vec3 mean = Vec3{sr[x], sg[x], sb[x]} / sw[x];
    r[x] = mean.x;
    g[x] = mean.y;
    b[x] = mean.z;
  }
  for (int x = cols.last; x < w; ++x) r[x] = g[x] = b[x] = 0.0f;
}

// What a pass needs of one signal.
struct PassSignal {
  RgbPlanes in, out;
  float *lum = nullptr, *inverseWidth = nullptr;
  float mean = 0.0f;                // of the luminance of the passes' input
  const float* variance = nullptr;  // unless null, replaces the neighbourhood's luminance variance where not negative
  std::vector<NonZeroColumns> columns;  // per row, where `in` is not zero
};

// One pass over one signal or two, tap by tap over whole rows so that the inner loop vectorises over contiguous
// pixels; every pixel still sums its taps in the (dy, dx) order of the CUDA version. In a row where both signals have
// pixels to give, the taps over the union of their columns are summed for both at once: outside its own columns a
// signal's taps are all zero, and so are its sums.
void atrousPass(Planes& planes, PassSignal* signals, int count, int w, int h, const AtrousPassConstants& k,
                float colorSigma) {
  tbb::parallel_for(0, h, [&](int y) {
    const size_t row = size_t(y) * w;
    for (int s = 0; s < count; ++s) {
      PassSignal& signal = signals[s];
      for (int x = 0; x < w; ++x) signal.lum[row + x] = luminance(signal.in.get(row + x));
      signal.columns[y] = nonZeroColumns(signal.in, row, w);
    }
  });
  tbb::parallel_for(0, h, [&](int y) {
    for (int s = 0; s < count; ++s) {
      const PassSignal& signal = signals[s];
      const NonZeroColumns cols = outputColumns(signal.columns, y, w, h, k.step);
      if (cols.first == cols.last) continue;  // the row's output is zero
      const size_t row = size_t(y) * w;
      float* widths = signal.inverseWidth + row;
      inverseColorWidthRow(signal.lum, w, h, y, colorSigma, signal.mean, widths);
      if (signal.variance)
        for (int x = 0; x < w; ++x)
          if (signal.variance[row + x] >= 0.0f)
            widths[x] = atrousInverseColorWidth(signal.variance[row + x], colorSigma, signal.mean);
    }
  });
  const float *nx = planes[kNx], *ny = planes[kNy], *nz = planes[kNz], *z = planes[kDepth];
  const float *slopeX = planes[kSlopeX], *slopeY = planes[kSlopeY];
  tbb::parallel_for(tbb::blocked_range<int>(0, h), [&](const tbb::blocked_range<int>& rows) {
    RowSums sums[2] = {RowSums{uint32_t(w)}, RowSums{uint32_t(w)}};
    for (int y = rows.begin(); y < rows.end(); ++y) {
      const size_t row = size_t(y) * w;
      NonZeroColumns cols[2];
      for (int s = 0; s < count; ++s) {
        cols[s] = outputColumns(signals[s].columns, y, w, h, k.step);
        sums[s].clear();
      }
      auto centreOf = [&](int s) {
        return CentreRow{
            signals[s].lum + row, signals[s].inverseWidth + row, nx + row, ny + row, nz + row, z + row, slopeX + row,
            slopeY + row};
      };
      auto tapsOf = [&](int s, size_t tapRow) {
        const RgbPlanes& in = signals[s].in;
        return TapRow{in.r + tapRow, in.g + tapRow, in.b + tapRow, signals[s].lum + tapRow,
                      nx + tapRow,   ny + tapRow,   nz + tapRow,   z + tapRow};
      };
      // Sums the taps of pixels [first, last) for signal `only`, or for both where it is -1; in spans short enough
      // that the rows a span reads stay in the L1 cache over its 25 taps.
      auto sumTaps = [&](int first, int last, int only) {
        const int s = only < 0 ? 0 : only;
        const CentreRow centre = centreOf(s);
        const SecondCentreRow centre1 =
            only < 0 ? SecondCentreRow{signals[1].lum + row, signals[1].inverseWidth + row} : SecondCentreRow{};
        for (int start = first; start < last; start += kSpan) {
          const int end = std::min(last, start + kSpan);
          for (int dy = -2; dy <= 2; ++dy) {
            const int qy = y + dy * k.step;
            if (qy < 0 || qy >= h) continue;
            const size_t tapRow = size_t(qy) * w;
            const TapRow tap = tapsOf(s, tapRow);
            for (int dx = -2; dx <= 2; ++dx) {
              const int ox = dx * k.step;
              if (dx == 0 && dy == 0) {
                accumulateCentre(tap, sums[s], start, end);
                if (only < 0) accumulateCentre(tapsOf(1, tapRow), sums[1], start, end);
              } else if (only < 0) {
                const RgbPlanes& in1 = signals[1].in;
                const SecondTapRow tap1{in1.r + tapRow, in1.g + tapRow, in1.b + tapRow, signals[1].lum + tapRow};
                accumulateTapOfTwo(centre, centre1, tap, tap1, sums[0], sums[1], std::max(start, -ox),
                                   std::min(end, w - ox), dx, dy, k);
              } else {
                accumulateTap(centre, tap, sums[s], std::max(start, -ox), std::min(end, w - ox), dx, dy, k);
              }
            }
          }
        }
      };
      const bool both = count == 2 && cols[0].first < cols[0].last && cols[1].first < cols[1].last;
      if (both) {
        sumTaps(std::min(cols[0].first, cols[1].first), std::max(cols[0].last, cols[1].last), -1);
      } else {
        for (int s = 0; s < count; ++s)
          if (cols[s].first < cols[s].last) sumTaps(cols[s].first, cols[s].last, s);
      }
      for (int s = 0; s < count; ++s) writeWeightedMeans(sums[s], cols[s], signals[s].out, row, w);
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
      aovs.emission.width != w || aovs.emission.height != h || aovs.depth.size() != size_t(w) * h ||
      aovs.variance.size() != size_t(w) * h || aovs.halvesVariance.size() != size_t(w) * h)
    throw std::invalid_argument("the a-trous filter's AOVs differ in size from the image");
}

AtrousWorkspace::AtrousWorkspace() = default;
AtrousWorkspace::~AtrousWorkspace() = default;

void AtrousWorkspace::setGuides(const AovImages& guides) {
  if (!stack_ || guides.width() != width_ || guides.height() != height_) {
    stack_.reset();
    width_ = guides.width();
    height_ = guides.height();
    stack_ = std::make_unique<PlaneStack>(kPlaneCount, size_t(width_) * height_);
  }
  Planes planes{*stack_};
  fillGuides(guides, planes);
}

RgbPlanes AtrousWorkspace::unitNormals() {
  Planes planes{*stack_};
  return {planes[kNx], planes[kNy], planes[kNz]};
}

RgbPlanes AtrousWorkspace::signal(int which) { return Planes{*stack_}.colour(which, 0); }

float* AtrousWorkspace::scratch() { return Planes{*stack_}.of(0, kInverseWidth); }

std::array<RgbPlanes, 2> AtrousWorkspace::runPasses(const AtrousParams& params, int signalCount,
                                                    const std::function<void(const RgbPlanes&)>& afterFirstPass,
                                                    const float* firstPassVariance) {
  Planes planes{*stack_};
  const int w = int(width_), h = int(height_);
  PassSignal signals[2];
  for (int s = 0; s < signalCount; ++s) {
    signals[s].mean = meanLuminance(planes.colour(s, 0), size_t(w) * h);
    signals[s].lum = planes.of(s, kLuminance);
    signals[s].inverseWidth = planes.of(s, kInverseWidth);
    signals[s].columns.resize(size_t(h));
  }
  if (params.passes == 0 && afterFirstPass) afterFirstPass(planes.colour(0, 0));
  for (int pass = 0; pass < params.passes; ++pass) {
    for (int s = 0; s < signalCount; ++s) {
      signals[s].in = planes.colour(s, pass % 2);
      signals[s].out = planes.colour(s, 1 - pass % 2);
      signals[s].variance = s == 0 && pass == 0 ? firstPassVariance : nullptr;
    }
    atrousPass(planes, signals, signalCount, w, h, atrousPassConstants(params, pass), params.colorSigma);
    if (pass == 0 && afterFirstPass) afterFirstPass(planes.colour(0, 1));
  }
  return {planes.colour(0, params.passes % 2), planes.colour(1, params.passes % 2)};
}

Image atrousDenoise(const Image& color, const AovImages& aovs, const AtrousParams& params) {
  validateAtrousInput(color, aovs, params);
  const int w = int(color.width), h = int(color.height);
  const size_t pixels = color.pixels.size();
  AtrousWorkspace workspace;
  workspace.setGuides(aovs);
  const RgbPlanes reflectedIn = workspace.signal(0);
  tbb::parallel_for(size_t(0), pixels, [&](size_t i) {
    reflectedIn.set(i, demodulate(color.pixels[i], aovs.emission.pixels[i], aovs.albedo.pixels[i]));
  });
  // Where the camera sees no emission the second signal's planes are left untouched (not even mapped).
  const bool emission =
      std::any_of(aovs.emission.pixels.begin(), aovs.emission.pixels.end(), [](Vec3 e) { return !isBlack(e); });
  if (emission) {
    const RgbPlanes emissionIn = workspace.signal(1);
    tbb::parallel_for(size_t(0), pixels,
                      [&](size_t i) { emissionIn.set(i, filterableEmission(aovs.emission.pixels[i])); });
  }
  const std::array<RgbPlanes, 2> filtered = workspace.runPasses(params, emission ? 2 : 1);
  // The variance of each pixel's mean (stratifiedVariance), in a plane the passes are done with.
  float* variance = workspace.scratch();
  auto boundAt = [&](int x, int y) { return aovs.variance[size_t(y) * w + x]; };
  auto halvesAt = [&](int x, int y) { return aovs.halvesVariance[size_t(y) * w + x]; };
  tbb::parallel_for(0, h, [&](int y) {
    for (int x = 0; x < w; ++x) variance[size_t(y) * w + x] = stratifiedVariance(boundAt, halvesAt, w, h, x, y);
  });
  auto varianceAt = [&](int x, int y) { return variance[size_t(y) * w + x]; };
  Image result(color.width, color.height);
  tbb::parallel_for(0, h, [&](int y) {
    for (int x = 0; x < w; ++x) {
      const size_t i = size_t(y) * w + x;
      const Vec3 reflected = remodulate(filtered[0].get(i), aovs.albedo.pixels[i]);
      const Vec3 filteredPixel = emission ? reflected + filtered[1].get(i) : reflected;
      result.pixels[i] = blendWithRaw(color.pixels[i], filteredPixel, blendVariance(varianceAt, w, h, x, y));
    }
  });
  return result;
}

}  // namespace candela
