#pragma once
// pbrt-v4's procedural cloud (CloudMedium::Density): octaves of Perlin noise at `frequency`, the lookup point
// perturbed by the noise's gradient where `wispiness` is positive, thinning with height and filled in below y = 0.5.
// The result lies in [0, 1], so the cloud's coefficients never exceed its sigma_a and sigma_s: its majorant is
// one voxel.
#include "kernel/media/perlin_noise.h"

namespace candela {

// The density at p, in the medium's own space (not normalised to its box, as in pbrt).
CANDELA_FN float cloudDensity(Vec3 p, float density, float wispiness, float frequency) {
  Vec3 pp = p * frequency;
  if (wispiness > 0.0f) {
    float vOmega = 0.05f * wispiness, vLambda = 10.0f;
    for (int i = 0; i < 2; ++i) {
      pp += perlinNoiseGradient(pp * vLambda) * vOmega;
      vOmega *= 0.5f;
      vLambda *= 1.99f;
    }
  }
  float d = 0.0f, omega = 0.5f, lambda = 1.0f;
  for (int i = 0; i < 5; ++i) {
    d += omega * perlinNoise(pp * lambda);
    omega *= 0.5f;
    lambda *= 1.99f;
  }
  d = clampf((1.0f - p.y) * 4.5f * density * d, 0.0f, 1.0f);
  d += 2.0f * fmaxf(0.0f, 0.5f - p.y);
  return clampf(d, 0.0f, 1.0f);
}

}  // namespace candela
