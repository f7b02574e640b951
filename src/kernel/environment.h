#pragma once
#include <cstdint>

#include "core/sampling.h"

namespace candela {

// The light arriving from infinitely far away, as kernel code reads it: either a constant `scale` from every
// direction, or `scale` times an equirectangular RGB map importance-sampled by a piecewise-constant 2D
// distribution over luminance * sin(theta) (pbrt-v3's Distribution2D).
//
// Map coordinates: +Y is up; v = theta / pi with theta measured from +Y (row 0 is the zenith); u = 0.5 is the
// -Z direction and u grows towards +X, so the middle of the image is what a camera looking down -Z sees.
// `rotationCos/Sin` turn the map about +Y.
struct EnvironmentView {
  Vec3 scale{0, 0, 0};
  const Vec3* texels = nullptr;  // width * height, top row first; null for a constant environment
  uint32_t width = 0;
  uint32_t height = 0;
  float rotationCos = 1.0f;
  float rotationSin = 0.0f;
  uint32_t visibleToCamera = 1;  // 0: camera rays that escape see black, while the map still lights the scene

  // The sampling distribution: density over (u, v) proportional to func[row * width + col].
  const float* func = nullptr;            // width * height
  const float* conditionalCdf = nullptr;  // height rows of width + 1 entries
  const float* marginalCdf = nullptr;     // height + 1 entries
  // Guide tables of the cdfs, shaped as they are (findGuidedInterval, core/sampling.h)
  const uint32_t* conditionalGuide = nullptr;
  const uint32_t* marginalGuide = nullptr;
  float funcAverage = 0.0f;  // mean of func: the normaliser of the (u, v) density
};

CANDELA_FN bool hasEnvironmentMap(const EnvironmentView& env) { return env.texels != nullptr; }

// Map (u, v) in [0, 1]^2 of a world direction (unit length), and back.
CANDELA_FN Vec2 environmentUv(const EnvironmentView& env, Vec3 d) {
  float x = env.rotationCos * d.x - env.rotationSin * d.z;  // rotate the world into the map by -angle
  float z = env.rotationSin * d.x + env.rotationCos * d.z;
  float u = 0.5f + atan2f(x, -z) * (0.5f * kInvPi);
  float v = acosf(clampf(d.y, -1.0f, 1.0f)) * kInvPi;
  return {u - floorf(u), v};
}
CANDELA_FN Vec3 environmentDirection(const EnvironmentView& env, Vec2 uv) {
  float phi = 2.0f * kPi * (uv.x - 0.5f), theta = kPi * uv.y;
  float sinTheta = sinf(theta);
  float x = sinTheta * sinf(phi), z = -sinTheta * cosf(phi);
  return {env.rotationCos * x + env.rotationSin * z, cosf(theta), -env.rotationSin * x + env.rotationCos * z};
}

// Bilinear lookup; wraps around in u, clamps at the poles.
CANDELA_FN Vec3 environmentTexel(const EnvironmentView& env, Vec2 uv) {
  float fx = uv.x * float(env.width) - 0.5f, fy = uv.y * float(env.height) - 0.5f;
  float x0f = floorf(fx), y0f = floorf(fy);
  float tx = fx - x0f, ty = fy - y0f;
  int w = int(env.width), h = int(env.height);
  int x0 = int(x0f) % w, y0 = int(y0f);
  if (x0 < 0) x0 += w;
  int x1 = x0 + 1 == w ? 0 : x0 + 1;
  int y1 = y0 + 1 > h - 1 ? h - 1 : y0 + 1;
  y0 = y0 < 0 ? 0 : (y0 > h - 1 ? h - 1 : y0);
  const Vec3* r0 = env.texels + size_t(y0) * env.width;
  const Vec3* r1 = env.texels + size_t(y1) * env.width;
  return (r0[x0] * (1.0f - tx) + r0[x1] * tx) * (1.0f - ty) + (r1[x0] * (1.0f - tx) + r1[x1] * tx) * ty;
}

// Radiance arriving along -direction, i.e. seen when looking along `direction` (pointing away from the scene).
CANDELA_FN Vec3 environmentRadiance(const EnvironmentView& env, Vec3 direction) {
  if (!hasEnvironmentMap(env)) return env.scale;
  return env.scale * environmentTexel(env, environmentUv(env, direction));
}

// Solid-angle density with which sampleEnvironment() returns `direction` (light selection not included).
CANDELA_FN float environmentDirectionPdf(const EnvironmentView& env, Vec3 direction) {
  if (!hasEnvironmentMap(env)) return uniformSpherePdf();
  if (!(env.funcAverage > 0.0f)) return 0.0f;
  Vec2 uv = environmentUv(env, direction);
  float sinTheta = sinf(kPi * uv.y);
  if (sinTheta <= 0.0f) return 0.0f;
  uint32_t col = uint32_t(uv.x * float(env.width)), row = uint32_t(uv.y * float(env.height));
  col = col < env.width ? col : env.width - 1;
  row = row < env.height ? row : env.height - 1;
  float uvPdf = env.func[size_t(row) * env.width + col] / env.funcAverage;
  return uvPdf / (2.0f * kPi * kPi * sinTheta);
}

struct EnvironmentSample {
  Vec3 direction;
  float pdf = 0.0f;  // solid angle
};

// Samples a continuous position inside a piecewise-constant 1D table: the bucket by its cdf (and the cdf's guide
// table), then uniformly in it.
CANDELA_FN float sampleCdfContinuous(const float* cdf, const uint32_t* guide, uint32_t n, float u, uint32_t& bucket) {
  bucket = uint32_t(findGuidedInterval(cdf, guide, int(n), u));
  float width = cdf[bucket + 1] - cdf[bucket];
  float du = width > 0.0f ? (u - cdf[bucket]) / width : 0.5f;
  return (float(bucket) + clampf(du, 0.0f, 0.99999994f)) / float(n);
}

CANDELA_FN EnvironmentSample sampleEnvironment(const EnvironmentView& env, Vec2 u) {
  EnvironmentSample s;
  if (!hasEnvironmentMap(env)) {
    s.direction = sampleUniformSphere(u);
    s.pdf = uniformSpherePdf();
    return s;
  }
  if (!(env.funcAverage > 0.0f)) return s;
  uint32_t row, col;
  float v = sampleCdfContinuous(env.marginalCdf, env.marginalGuide, env.height, u.y, row);
  const size_t rowStart = size_t(row) * (env.width + 1);
  float uu = sampleCdfContinuous(env.conditionalCdf + rowStart, env.conditionalGuide + rowStart, env.width, u.x, col);
  float sinTheta = sinf(kPi * v);
  if (sinTheta <= 0.0f) return s;
  s.direction = environmentDirection(env, {uu, v});
  s.pdf = env.func[size_t(row) * env.width + col] / env.funcAverage / (2.0f * kPi * kPi * sinTheta);
  return s;
}

}  // namespace candela
