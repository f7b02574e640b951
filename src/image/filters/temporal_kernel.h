#pragma once
// The temporal filter's per-pixel arithmetic (SVGF's reprojection and accumulation, Schied et al. 2017), shared by
// the CPU filter (temporal.cpp) and its CUDA version, which make the same decisions in the same order.
#include "core/math.h"
#include "kernel/camera.h"

namespace candela {

// What the temporal filter keeps of a pixel from frame to frame: its accumulated light (the reflected part
// demodulated by the albedo, the emitted part as it is), how many samples' worth that is, and the first two moments
// of the luminance of the reflected part over the frames, for the variance of the accumulated mean.
struct TemporalSample {
  Vec3 reflected, emission;
  float length = 0.0f;  // samples' worth; 0: no history
  float moment1 = 0.0f, moment2 = 0.0f;
};

// The guides of a pixel: the unit normal (zero where the path escaped), the depth (zero there too), and whether the
// camera sees light emitted there (for the history: whether its accumulated emission is not zero).
struct TemporalGuides {
  Vec3 normal;
  float depth;
  bool emissive;
};

struct TemporalLimits {
  float maxHistory;       // a reprojected history counts as at most this many samples
  float depthTolerance;   // relative difference of depths that still is the same surface
  float normalTolerance;  // the least cosine between normals of the same surface
};

// The direction from `camera` through film point (px, py) in pixels, of a pinhole (a thin lens's centre ray).
CANDELA_FN Vec3 cameraDirection(const Camera& camera, float px, float py, int w, int h) {
  const float sx = 2.0f * px / float(w) - 1.0f, sy = 1.0f - 2.0f * py / float(h);
  return normalize(camera.forward + camera.right * sx + camera.up * sy);
}

// Where `offset` (a point minus the camera's position, or a direction for a point at infinity) lands on the film of
// `camera` (w x h pixels, (0, 0) the top-left corner), and a number that is positive where it lies in front of the
// camera (px, py are then finite or infinite; otherwise they mean nothing). Without branches, so that loops over
// pixels vectorise.
CANDELA_FN float filmPosition(const Camera& camera, Vec3 offset, int w, int h, float& px, float& py) {
  const float z = dot(offset, camera.forward);
  const float inverseZ = 1.0f / (z > 0.0f ? z : 1.0f);
  const float sx = dot(offset, camera.right) / dot(camera.right, camera.right) * inverseZ;
  const float sy = dot(offset, camera.up) / dot(camera.up, camera.up) * inverseZ;
  px = (sx + 1.0f) * 0.5f * float(w);
  py = (1.0f - sy) * 0.5f * float(h);
  return z - 1e-6f * sqrtf(dot(offset, offset));
}

// Whether a pixel of this mean emission shows an emitter.
CANDELA_FN bool isEmissive(Vec3 emission) { return emission.x + emission.y + emission.z > 0.0f; }

// Whether the history pixel with `guides` shows the surface the current pixel sees (`current`): both escaped to the
// sky, or both hit a surface at the depth the previous camera would see the current point at, with normals that
// agree; and both emit or neither does (a light is often flush with the surface around it: its light reprojected
// onto that surface, or the surface's history onto the light, would stay there for many frames). At an emitter's
// edge, where a pixel's samples hit it or miss it, the history is then often rejected; the a-trous passes over the
// emission smooth what is left there.
CANDELA_FN bool sameSurface(TemporalGuides history, TemporalGuides current, float expectedDepth,
                            const TemporalLimits& limits) {
  if (history.emissive != current.emissive) return false;
  const bool escaped = current.depth == 0.0f;
  if (escaped || history.depth == 0.0f) return escaped && history.depth == 0.0f;
  if (fabsf(history.depth - expectedDepth) > limits.depthTolerance * expectedDepth) return false;
  return dot(history.normal, current.normal) >= limits.normalTolerance;
}

// Where the first hit of pixel (x, y) lay on the previous film: the film point (px, py) in pixels at which the
// previous camera saw it, and the distance it then lay at (0 for a path that escaped: then the point is the
// direction's, at infinity). `onFilm` is false where the point lay behind the previous camera or off its film.
// Without branches, so that a CPU loop over a row of pixels vectorises.
struct PreviousFilmPoint {
  float px, py, expectedDepth;
  bool onFilm;
};

CANDELA_FN PreviousFilmPoint previousFilmPoint(const Camera& current, const Camera& previous, int w, int h, int x,
                                               int y, float depth) {
  const Vec3 direction = cameraDirection(current, float(x) + 0.5f, float(y) + 0.5f, w, h);
  const bool escaped = depth == 0.0f;
  const Vec3 offset = escaped ? direction : current.position + direction * depth - previous.position;
  PreviousFilmPoint p;
  const float front = filmPosition(previous, offset, w, h, p.px, p.py);
  p.expectedDepth = escaped ? 0.0f : sqrtf(dot(offset, offset));
  // In front of the camera, px in (-0.5, w + 1.5) and py likewise: where a pixel around the point lies inside the
  // film (at px = -0.5 exactly only pixel -1 has weight). One comparison of the least margin rather than a chain of
  // them keeps the CPU loop vectorisable (as minima by comparison: fminf does not vectorise). A NaN px or py comes
  // only with a NaN front, which the last minimum keeps.
  auto least = [](float a, float b) { return a < b ? a : b; };
  const float margin = least(least(p.px + 0.5f, p.py + 0.5f), least(float(w) + 1.5f - p.px, float(h) + 1.5f - p.py));
  p.onFilm = least(margin, front) > 0.0f;
  return p;
}

// The history of a pixel with `guides` whose first hit the previous camera saw at `point`, reprojected from the
// previous frame: the bilinear mix of the (up to four) previous pixels around point that show the same surface. No
// history (length 0) where none does or the point was off the previous film. historyAt(qx, qy, guides) returns the
// TemporalSample of previous pixel (qx, qy), inside the film, and sets its guides.
template <class HistoryAt>
CANDELA_HD TemporalSample gatherHistory(const PreviousFilmPoint& point, int w, int h, TemporalGuides guides,
                                        const TemporalLimits& limits, const HistoryAt& historyAt) {
  TemporalSample none;
  if (!point.onFilm) return none;
  const float fx = point.px - 0.5f, fy = point.py - 0.5f;
  const float x0f = floorf(fx), y0f = floorf(fy);
  const int x0 = int(x0f), y0 = int(y0f);
  const float tx = fx - x0f, ty = fy - y0f;
  TemporalSample sum;
  float weights = 0.0f;
  for (int dy = 0; dy <= 1; ++dy)
    for (int dx = 0; dx <= 1; ++dx) {
      const int qx = x0 + dx, qy = y0 + dy;
      if (qx < 0 || qy < 0 || qx >= w || qy >= h) continue;
      const float weight = (dx ? tx : 1.0f - tx) * (dy ? ty : 1.0f - ty);
      if (weight <= 0.0f) continue;
      TemporalGuides qGuides;
      const TemporalSample q = historyAt(qx, qy, qGuides);
      if (q.length <= 0.0f || !sameSurface(qGuides, guides, point.expectedDepth, limits)) continue;
      sum.reflected = sum.reflected + q.reflected * weight;
      sum.emission = sum.emission + q.emission * weight;
      sum.length += q.length * weight;
      sum.moment1 += q.moment1 * weight;
      sum.moment2 += q.moment2 * weight;
      weights += weight;
    }
  if (weights < 1e-3f) return none;
  const float inverse = 1.0f / weights;
  sum.reflected = sum.reflected * inverse;
  sum.emission = sum.emission * inverse;
  sum.moment1 *= inverse;
  sum.moment2 *= inverse;
  sum.length = fminf(sum.length * inverse, limits.maxHistory);
  return sum;
}

// The history of pixel (x, y), whose first hit lies at guides.depth along its centre ray from `current` (0: the path
// escaped), reprojected from the previous frame seen by `previous` (gatherHistory at previousFilmPoint).
template <class HistoryAt>
CANDELA_HD TemporalSample reprojectHistory(const Camera& current, const Camera& previous, int w, int h, int x, int y,
                                           TemporalGuides guides, const TemporalLimits& limits,
                                           const HistoryAt& historyAt) {
  return gatherHistory(previousFilmPoint(current, previous, w, h, x, y, guides.depth), w, h, guides, limits, historyAt);
}

// The history `base` (length in samples' worth) and the current film's mean of `samples` samples, weighted by their
// counts: where the history is short the film counts more, so disoccluded pixels take the new frame alone. The
// moments count each frame's mean as one value of the luminance.
CANDELA_FN TemporalSample accumulateTemporal(const TemporalSample& base, Vec3 reflected, Vec3 emission, float samples) {
  const float total = base.length + samples, a = samples / total;
  TemporalSample out;
  out.reflected = base.reflected + (reflected - base.reflected) * a;
  out.emission = base.emission + (emission - base.emission) * a;
  const float l = luminance(reflected);
  const bool fresh = base.length <= 0.0f;
  out.moment1 = fresh ? l : base.moment1 + (l - base.moment1) * a;
  out.moment2 = fresh ? l * l : base.moment2 + (l * l - base.moment2) * a;
  out.length = total;
  return out;
}

// The variance of the accumulated mean luminance of the reflected light, for the a-trous filter's first colour
// widths: the variance of the frames' luminance (moments) over the frames accumulated, each of `samples` samples.
// Negative (not known: the filter estimates it from the neighbourhood) until the history holds four frames.
constexpr float kTemporalVarianceFrames = 4.0f;
CANDELA_FN float temporalVariance(const TemporalSample& s, float samples) {
  if (s.length < kTemporalVarianceFrames * samples) return -1.0f;
  const float spread = s.moment2 - s.moment1 * s.moment1;
  return (spread > 0.0f ? spread : 0.0f) * samples / s.length;
}

}  // namespace candela
