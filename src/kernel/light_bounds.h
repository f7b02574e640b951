#pragma once
#include "core/math.h"

namespace candela {

// What a light or a group of lights can send anywhere, as pbrt-v4's LightBounds: a box holding them, their
// total power, and the directions they emit along: within cosThetaO of the axis `w` lie all their normals, and
// each emits within cosThetaE beyond its normal (0 for a one-sided area light: a hemisphere).
struct LightBounds {
  Vec3 lo, hi;
  Vec3 w{0, 0, 1};
  float phi = 0.0f;  // emitted power (luminance)
  float cosThetaO = 1.0f;
  float cosThetaE = 0.0f;
  uint32_t twoSided = 0;
};

// LightBounds as the sampler reads them: the box by its bounding sphere, which is all the importance needs of
// it, and the cone's sine precomputed.
struct CompactLightBounds {
  Vec3 centre;
  float radius = 0.0f;  // half the box's diagonal
  Vec3 w{0, 0, 1};
  float phi = 0.0f;
  float cosThetaO = 1.0f, sinThetaO = 0.0f;
  float cosThetaE = 0.0f;
  uint32_t twoSided = 0;
};

CANDELA_FN CompactLightBounds compact(const LightBounds& b) {
  CompactLightBounds c;
  c.centre = (b.lo + b.hi) * 0.5f;
  c.radius = 0.5f * length(b.hi - b.lo);
  c.w = b.w;
  c.phi = b.phi;
  c.cosThetaO = b.cosThetaO;
  c.sinThetaO = sqrtf(fmaxf(0.0f, 1.0f - b.cosThetaO * b.cosThetaO));
  c.cosThetaE = b.cosThetaE;
  c.twoSided = b.twoSided;
  return c;
}

// Where a light is sampled from: the shading point and its normal (zero where there is no surface).
struct LightSampleContext {
  Vec3 p;
  Vec3 n;
};

namespace detail {

CANDELA_FN float safeSqrt(float x) { return sqrtf(fmaxf(x, 0.0f)); }

// cos(a - b) and sin(a - b) for angles a and b given by their cosines and sines, clamped to 0 where a < b.
CANDELA_FN float cosSubClamped(float sinA, float cosA, float sinB, float cosB) {
  return cosA > cosB ? 1.0f : cosA * cosB + sinA * sinB;
}
CANDELA_FN float sinSubClamped(float sinA, float cosA, float sinB, float cosB) {
  return cosA > cosB ? 0.0f : sinA * cosB - cosA * sinB;
}

}  // namespace detail

// An estimate of how much light from `b` reaches a surface at ctx, as pbrt-v4's LightBounds::Importance: power
// over squared distance, times the cosine of the smallest angle between the emission cone and the direction to
// ctx, and of the smallest angle between the surface normal and any direction to the box. It is zero only where
// no light in `b` can reach ctx.
CANDELA_FN float lightImportance(const CompactLightBounds& b, LightSampleContext ctx) {
  using namespace detail;
  Vec3 toPoint = ctx.p - b.centre;
  float dist2 = dot(toPoint, toPoint);
  // Clamped as pbrt does (to half the box's diagonal), so that points in or near the box do not get unbounded
  // importance.
  float d2 = fmaxf(dist2, b.radius);
  float invDist = dist2 > 0.0f ? 1.0f / sqrtf(dist2) : 0.0f;

  // Angle between the cone axis and the direction from the box to the point.
  Vec3 wi = toPoint * invDist;
  float cosThetaW = dot(b.w, wi);
  if (b.twoSided) cosThetaW = fabsf(cosThetaW);
  float sinThetaW = safeSqrt(1.0f - cosThetaW * cosThetaW);

  // Half-angle of the cone of directions from the point to the box's bounding sphere; all of them at the inside.
  bool inside = dist2 < b.radius * b.radius;
  float sinThetaB = inside ? 0.0f : b.radius * invDist;
  float cosThetaB = inside ? -1.0f : safeSqrt(1.0f - sinThetaB * sinThetaB);

  // The smallest angle between an emission direction and a direction to the point, against the emission cutoff.
  float cosThetaX = cosSubClamped(sinThetaW, cosThetaW, b.sinThetaO, b.cosThetaO);
  float sinThetaX = sinSubClamped(sinThetaW, cosThetaW, b.sinThetaO, b.cosThetaO);
  float cosThetaP = cosSubClamped(sinThetaX, cosThetaX, sinThetaB, cosThetaB);
  if (cosThetaP <= b.cosThetaE) return 0.0f;

  float importance = b.phi * cosThetaP / d2;
  if (ctx.n.x != 0.0f || ctx.n.y != 0.0f || ctx.n.z != 0.0f) {
    float cosThetaI = fabsf(dot(wi, ctx.n));
    float sinThetaI = safeSqrt(1.0f - cosThetaI * cosThetaI);
    importance *= cosSubClamped(sinThetaI, cosThetaI, sinThetaB, cosThetaB);
  }
  return fmaxf(importance, 0.0f);
}

}  // namespace candela
