#include "image/filters/temporal.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <array>
#include <stdexcept>
#include <vector>

#include "image/filters/atrous_kernel.h"
#include "image/filters/temporal_kernel.h"

namespace candela {

namespace {

// previousFilmPoint of a row's pixels, field by field.
struct PreviousFilmRow {
  std::vector<float> px, py, expectedDepth;
  std::vector<uint32_t> onFilm;  // 32 bits, as wide as the other fields: the loop vectorises
  explicit PreviousFilmRow(size_t width) : px(width), py(width), expectedDepth(width), onFilm(width) {}
  PreviousFilmPoint at(int x) const { return {px[x], py[x], expectedDepth[x], onFilm[x] != 0}; }
};

// previousFilmPoint of every pixel of row y, whose depths are `depth`, in a loop that vectorises. Compiled for
// x86-64-v4 (AVX-512) and -v3 (AVX2, FMA) as well as the baseline instruction set, chosen at run time.
__attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default"))) void previousFilmRow(
    const Camera& current, const Camera& previous, int w, int h, int y, const float* depth, PreviousFilmRow& out) {
  float *px = out.px.data(), *py = out.py.data(), *expectedDepth = out.expectedDepth.data();
  uint32_t* onFilm = out.onFilm.data();
  const Camera now = current, before = previous;  // copies, which the row's stores cannot alias
  for (int x = 0; x < w; ++x) {
    const PreviousFilmPoint p = previousFilmPoint(now, before, w, h, x, y, depth[x]);
    px[x] = p.px;
    py[x] = p.py;
    expectedDepth[x] = p.expectedDepth;
    onFilm[x] = uint32_t(p.onFilm);
  }
}

}  // namespace

void validateTemporalParams(const TemporalParams& params) {
  validateAtrousParams(params.atrous);
  if (!(params.maxHistory >= 1.0f && params.maxHistory <= 1e6f))
    throw std::invalid_argument("the temporal filter's history must count between 1 and 1e6 samples");
  if (!(params.depthTolerance > 0.0f) || !(params.normalTolerance >= -1.0f && params.normalTolerance <= 1.0f))
    throw std::invalid_argument("the temporal filter's depth tolerance must be positive, its normal one a cosine");
}

void TemporalFilter::History::resize(size_t pixels) {
  reflected.assign(pixels, Vec3{});
  emission.assign(pixels, Vec3{});
  normal.assign(pixels, Vec3{});
  length.assign(pixels, 0.0f);
  moment1.assign(pixels, 0.0f);
  moment2.assign(pixels, 0.0f);
  depth.assign(pixels, 0.0f);
  emissive.assign(pixels, 0);
}

TemporalFilter::TemporalFilter(TemporalParams params) : params_(params) { validateTemporalParams(params_); }

void TemporalFilter::reset() {
  haveHistory_ = false;
  width_ = height_ = 0;
}

Image TemporalFilter::filter(const TemporalFrame& frame) {
  validateAtrousInput(frame.color, frame.aovs, params_.atrous);
  const int w = int(frame.color.width), h = int(frame.color.height);
  const size_t pixels = frame.color.pixels.size();
  if (frame.color.width != width_ || frame.color.height != height_) {
    width_ = frame.color.width;
    height_ = frame.color.height;
    haveHistory_ = false;
    base_.resize(pixels);
    last_.resize(pixels);
  }
  const TemporalLimits limits{params_.maxHistory, params_.depthTolerance, params_.normalTolerance};
  const AovImages& aovs = frame.aovs;

  // The guides of the a-trous passes, whose unit normals the reprojection and the new history take too.
  workspace_.setGuides(aovs);
  const RgbPlanes normals = workspace_.unitNormals();

  // The history this film starts from: the last frame's reprojected, unless the film goes on from that frame's.
  if (!frame.filmContinues) {
    tbb::parallel_for(tbb::blocked_range<int>(0, h), [&](const tbb::blocked_range<int>& rows) {
      PreviousFilmRow points{size_t(w)};
      for (int y = rows.begin(); y < rows.end(); ++y) {
        const size_t row = size_t(y) * w;
        if (haveHistory_) previousFilmRow(frame.camera, camera_, w, h, y, aovs.depth.data() + row, points);
        for (int x = 0; x < w; ++x) {
          const size_t i = row + x;
          TemporalSample s;
          if (haveHistory_) {
            auto historyAt = [&](int qx, int qy, TemporalGuides& guides) {
              const size_t q = size_t(qy) * w + qx;
              guides = {last_.normal[q], last_.depth[q], last_.emissive[q] != 0};
              return TemporalSample{last_.reflected[q], last_.emission[q], last_.length[q], last_.moment1[q],
                                    last_.moment2[q]};
            };
            const TemporalGuides guides{normals.get(i), aovs.depth[i], isEmissive(aovs.emission.pixels[i])};
            s = gatherHistory(points.at(x), w, h, guides, limits, historyAt);
          }
          base_.reflected[i] = s.reflected;
          base_.emission[i] = s.emission;
          base_.length[i] = s.length;
          base_.moment1[i] = s.moment1;
          base_.moment2[i] = s.moment2;
        }
      }
    });
  }

  // The film added to it, straight into the planes of the a-trous passes: the reflected light and the accumulated
  // emission (kept in the new history too).
  const RgbPlanes signal = workspace_.signal(0), emissionSignal = workspace_.signal(1);
  variance_.resize(pixels);
  const float samples = float(frame.samples > 0 ? frame.samples : 1);
  tbb::parallel_for(size_t(0), pixels, [&](size_t i) {
    const TemporalSample base{base_.reflected[i], base_.emission[i], base_.length[i], base_.moment1[i],
                              base_.moment2[i]};
    const TemporalSample s =
        accumulateTemporal(base, demodulate(frame.color.pixels[i], aovs.emission.pixels[i], aovs.albedo.pixels[i]),
                           filterableEmission(aovs.emission.pixels[i]), samples);
    signal.set(i, s.reflected);
    emissionSignal.set(i, s.emission);
    variance_[i] = temporalVariance(s, samples);
    last_.emission[i] = s.emission;
    last_.length[i] = s.length;
    last_.moment1[i] = s.moment1;
    last_.moment2[i] = s.moment2;
    last_.normal[i] = normals.get(i);
    last_.depth[i] = aovs.depth[i];
    last_.emissive[i] = isEmissive(s.emission);
  });
  // The first level of the reflected light becomes the next frame's history.
  const std::array<RgbPlanes, 2> filtered = workspace_.runPasses(
      params_.atrous, 2,
      [&](const RgbPlanes& level) {
        tbb::parallel_for(size_t(0), pixels, [&](size_t i) { last_.reflected[i] = level.get(i); });
      },
      variance_.data());
  Image result(width_, height_);
  tbb::parallel_for(size_t(0), pixels, [&](size_t i) {
    result.pixels[i] = remodulate(filtered[0].get(i), aovs.albedo.pixels[i]) + filtered[1].get(i);
  });
  camera_ = frame.camera;
  haveHistory_ = true;
  return result;
}

}  // namespace candela
