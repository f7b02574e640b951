#pragma once
// The Henyey-Greenstein phase function, with pbrt-v4's conventions (HGPhaseFunction, SampleHenyeyGreenstein): both
// directions point away from the scattering point, wo back along the incoming ray, so forward scattering (g > 0)
// favours wi near -wo and the density is a function of cos = dot(wo, wi). Sampling it is exact: the sampled
// direction's weight p / pdf is 1.
#include "core/math.h"

namespace candela {

struct PhaseSample {
  Vec3 wi;
  float pdf = 0.0f;  // solid-angle density, equal to the phase function's value
};

// p(cos) = (1 - g^2) / (4 pi (1 + g^2 + 2 g cos)^(3/2)), cos = dot(wo, wi).
CANDELA_FN float henyeyGreenstein(float cosTheta, float g) {
  const float denom = 1.0f + g * g + 2.0f * g * cosTheta;
  return (1.0f - g * g) / (4.0f * kPi * denom * sqrtf(fmaxf(denom, 0.0f)));
}

CANDELA_FN float henyeyGreensteinPdf(Vec3 wo, Vec3 wi, float g) { return henyeyGreenstein(dot(wo, wi), g); }

// Inverts the distribution of cos about wo; below |g| = 1e-3 the inversion loses its digits and the uniform
// sphere is sampled instead (pbrt-v4 does the same).
CANDELA_FN PhaseSample sampleHenyeyGreenstein(Vec3 wo, float g, Vec2 u) {
  float cosTheta;
  if (fabsf(g) < 1e-3f) {
    cosTheta = 1.0f - 2.0f * u.x;
  } else {
    const float q = (1.0f - g * g) / (1.0f + g - 2.0f * g * u.x);
    cosTheta = -(1.0f + g * g - q * q) / (2.0f * g);
  }
  cosTheta = fminf(fmaxf(cosTheta, -1.0f), 1.0f);
  const float sinTheta = sqrtf(fmaxf(0.0f, 1.0f - cosTheta * cosTheta));
  const float phi = 2.0f * kPi * u.y;
  const Frame frame = Frame::fromNormal(wo);
  PhaseSample s;
  s.wi = normalize(frame.toWorld({sinTheta * cosf(phi), sinTheta * sinf(phi), cosTheta}));
  s.pdf = henyeyGreenstein(cosTheta, g);
  return s;
}

}  // namespace candela
