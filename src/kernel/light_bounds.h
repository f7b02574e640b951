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

// Where a light is sampled from: the shading point and its normal (zero where there is no surface); or, with a
// radius, any point within that distance of p, its normal within the angle whose cosine and sine are
// cosNormalSpread and sinNormalSpread of n (a region of shading points, as ReSTIR's presampling sees a screen tile).
struct LightSampleContext {
  Vec3 p;
  Vec3 n;
  float radius = 0.0f;
  float cosNormalSpread = 1.0f, sinNormalSpread = 0.0f;
};

namespace detail {

// a where a > b, else b (b also where a is NaN): fmaxf for these operands, without the call into libm that IEEE fmax
// costs on the CPU (the importance is evaluated at every level of every walk down the light BVH).
CANDELA_FN float largerOf(float a, float b) { return a > b ? a : b; }
// a where a < b, else b: fminf for these operands, likewise.
CANDELA_FN float smallerOf(float a, float b) { return a < b ? a : b; }

CANDELA_FN float safeSqrt(float x) { return sqrtf(largerOf(x, 0.0f)); }

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
// no light in `b` can reach ctx. A region (ctx.radius > 0) is bounded together with the box: every direction from a
// point of the box's sphere to a point of the region lies within the angle that the two radii's sum subtends at the
// distance between the centres, so the importance is zero only where no light in `b` can reach any point of it.
CANDELA_FN float lightImportance(const CompactLightBounds& b, LightSampleContext ctx) {
  using namespace detail;
  Vec3 toPoint = ctx.p - b.centre;
  float dist2 = dot(toPoint, toPoint);
  const float radius = b.radius + ctx.radius;
  // Clamped as pbrt does (to half the box's diagonal), so that points in or near the box do not get unbounded
  // importance.
  float d2 = largerOf(dist2, radius);
  float invDist = dist2 > 0.0f ? 1.0f / sqrtf(dist2) : 0.0f;

  // Angle between the cone axis and the direction from the box to the point.
  Vec3 wi = toPoint * invDist;
  float cosThetaW = dot(b.w, wi);
  if (b.twoSided) cosThetaW = fabsf(cosThetaW);
  float sinThetaW = safeSqrt(1.0f - cosThetaW * cosThetaW);

  // Half-angle of the cone of directions from the point to the box's bounding sphere; all of them at the inside.
  bool inside = dist2 < radius * radius;
  float sinThetaB = inside ? 0.0f : radius * invDist;
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
    // The smallest angle between a normal of the region and a direction to the box: theta_I less theta_B and the
    // normals' spread (exactly theta_B where there is one normal: cos 1, sin 0).
    float cosThetaBN = cosThetaB * ctx.cosNormalSpread - sinThetaB * ctx.sinNormalSpread;
    float sinThetaBN = sinThetaB * ctx.cosNormalSpread + cosThetaB * ctx.sinNormalSpread;
    if (cosThetaBN > 0.0f) importance *= cosSubClamped(sinThetaI, cosThetaI, sinThetaBN, cosThetaBN);
  }
  return largerOf(importance, 0.0f);
}

}  // namespace candela
