#pragma once
#include "core/math.h"

namespace candela {

// The solid angle a triangle subtends seen from p (Van Oosterom and Strackee 1983), from the unit directions
// a, b, c towards its corners.
CANDELA_FN float sphericalTriangleArea(Vec3 a, Vec3 b, Vec3 c) {
  return fabsf(2.0f * atan2f(dot(a, cross(b, c)), 1.0f + dot(a, b) + dot(a, c) + dot(b, c)));
}

namespace detail {

// The angle between unit vectors, accurate also where they are nearly parallel (as pbrt-v4's AngleBetween).
CANDELA_FN float angleBetweenUnit(Vec3 a, Vec3 b) {
  if (dot(a, b) < 0.0f) return kPi - 2.0f * asinf(fminf(1.0f, 0.5f * length(a + b)));
  return 2.0f * asinf(fminf(1.0f, 0.5f * length(b - a)));
}

// The part of v perpendicular to the unit vector w, normalised.
CANDELA_FN Vec3 orthonormalPart(Vec3 v, Vec3 w) { return normalize(v - w * dot(v, w)); }

}  // namespace detail

struct SphericalTriangleSample {
  Vec2 barycentrics;  // of the triangle's corners 1 and 2, of the point the sampled direction reaches
  float pdf = 0.0f;   // with respect to solid angle: 1 / the triangle's solid angle; 0 where sampling failed
};

// The triangle (p0, p1, p2) as seen from p: the unit directions towards its corners and the solid angle they span.
struct SphericalTriangle {
  Vec3 a, b, c;
  float area = 0.0f;
};

CANDELA_FN SphericalTriangle sphericalTriangle(Vec3 p0, Vec3 p1, Vec3 p2, Vec3 p) {
  SphericalTriangle t;
  t.a = normalize(p0 - p);
  t.b = normalize(p1 - p);
  t.c = normalize(p2 - p);
  t.area = sphericalTriangleArea(t.a, t.b, t.c);
  return t;
}

// A direction from p distributed uniformly over the solid angle of the triangle (p0, p1, p2), whose view from p
// is `seen`, as the point it reaches on the triangle (Arvo 1995, as pbrt-v4's SampleSphericalTriangle). Fails for
// triangles that are too small or too large seen from p for single precision: callers sample those by area.
CANDELA_FN SphericalTriangleSample sampleSphericalTriangle(const SphericalTriangle& seen, Vec3 p0, Vec3 p1, Vec3 p2,
                                                           Vec3 p, Vec2 u) {
  using namespace detail;
  SphericalTriangleSample s;
  const Vec3 a = seen.a, b = seen.b, c = seen.c;
  Vec3 nab = cross(a, b), nbc = cross(b, c), nca = cross(c, a);
  if (dot(nab, nab) == 0.0f || dot(nbc, nbc) == 0.0f || dot(nca, nca) == 0.0f) return s;
  nab = normalize(nab);
  nbc = normalize(nbc);
  nca = normalize(nca);
  // The spherical triangle's angles at its corners; their sum less pi is its area.
  float alpha = angleBetweenUnit(nab, -nca);
  float beta = angleBetweenUnit(nbc, -nab);
  float gamma = angleBetweenUnit(nca, -nbc);
  float areaPlusPi = alpha + beta + gamma;
  float area = areaPlusPi - kPi;
  if (!(area > 0.0f)) return s;

  // The sub-triangle (a, b, c') with area u.x times the whole: c' on the arc from a to c.
  float sampledPlusPi = lerp(u.x, kPi, areaPlusPi);
  float cosAlpha = cosf(alpha), sinAlpha = sinf(alpha);
  float sinPhi = sinf(sampledPlusPi) * cosAlpha - cosf(sampledPlusPi) * sinAlpha;
  float cosPhi = cosf(sampledPlusPi) * cosAlpha + sinf(sampledPlusPi) * sinAlpha;
  float k1 = cosPhi + cosAlpha;
  float k2 = sinPhi - sinAlpha * dot(a, b);
  float cosBp = (k2 + (k2 * cosPhi - k1 * sinPhi) * cosAlpha) / ((k2 * sinPhi + k1 * cosPhi) * sinAlpha);
  if (!(cosBp == cosBp)) return s;  // NaN: the triangle covers about a hemisphere
  cosBp = clampf(cosBp, -1.0f, 1.0f);
  float sinBp = sqrtf(fmaxf(0.0f, 1.0f - cosBp * cosBp));
  Vec3 cp = a * cosBp + orthonormalPart(c, a) * sinBp;

  // A direction on the arc from b to c', distributed so that the sub-triangles' areas are uniform.
  float cosTheta = 1.0f - u.y * (1.0f - dot(cp, b));
  float sinTheta = sqrtf(fmaxf(0.0f, 1.0f - cosTheta * cosTheta));
  Vec3 w = b * cosTheta + orthonormalPart(cp, b) * sinTheta;

  // Where it meets the triangle's plane, as barycentrics (Moller-Trumbore).
  Vec3 e1 = p1 - p0, e2 = p2 - p0;
  Vec3 s1 = cross(w, e2);
  float divisor = dot(s1, e1);
  if (divisor == 0.0f) return s;
  Vec3 toP = p - p0;
  float b1 = clampf(dot(toP, s1) / divisor, 0.0f, 1.0f);
  float b2 = clampf(dot(w, cross(toP, e1)) / divisor, 0.0f, 1.0f);
  if (b1 + b2 > 1.0f) {
    float sum = b1 + b2;
    b1 /= sum;
    b2 /= sum;
  }
  s.barycentrics = {b1, b2};
  // The area from the corners' angles loses precision to cancellation for small triangles; the pdf comes from
  // the accurate formula, the one a caller evaluating the density of a direction uses too.
  s.pdf = 1.0f / seen.area;
  return s;
}

CANDELA_FN SphericalTriangleSample sampleSphericalTriangle(Vec3 p0, Vec3 p1, Vec3 p2, Vec3 p, Vec2 u) {
  return sampleSphericalTriangle(sphericalTriangle(p0, p1, p2, p), p0, p1, p2, p, u);
}

}  // namespace candela
