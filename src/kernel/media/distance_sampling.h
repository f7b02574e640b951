#pragma once
// Free-flight sampling in a homogeneous medium: delta tracking whose majorant is the medium's own sigma_t, so that
// every tentative collision is a real one and tracking reduces to sampling the exponential distribution exactly.
//
// The three RGB channels have three sigma_t. As pbrt-v4 samples distances with its hero wavelength and weighs the
// others by their densities (single-sample MIS over wavelengths), one channel, chosen uniformly, sets the
// distance, and every channel is weighed by the balance heuristic over the three: the estimate divides by the
// channels' mean density, which no channel can make zero where another could have sampled the distance. A
// channel that does not interact (sigma_t 0) never stops the ray.
#include "kernel/media/medium.h"

namespace candela {

// Where a ray segment through a medium ends, and what its throughput is multiplied by.
struct MediumStep {
  bool scattered = false;  // true: at distance t, inside the segment; false: the segment's end is reached
  float t = 0.0f;
  // scattered: T(t) sigma_s / pdf(t), the throughput's factor through the segment and the scattering there;
  // else T(tMax) / P(reach tMax).
  Vec3 weight;
  // scattered: T(t) sigma_a Le / pdf(t), what the medium's emission adds (times the throughput before the step).
  Vec3 emission;
};

// The mean over the channels of sigma_t exp(-sigma_t t) (the density of stopping at t) and of exp(-sigma_t t)
// (the probability of passing t).
CANDELA_FN float meanCollisionDensity(Vec3 sigmaT, Vec3 transmittance) {
  return (sigmaT.x * transmittance.x + sigmaT.y * transmittance.y + sigmaT.z * transmittance.z) * (1.0f / 3.0f);
}
CANDELA_FN float meanPassProbability(Vec3 transmittance) {
  return (transmittance.x + transmittance.y + transmittance.z) * (1.0f / 3.0f);
}

// Samples where a ray in medium m, whose segment ends at tMax (infinite where it escapes), first collides: uChannel
// picks the channel that samples, uDistance the distance.
CANDELA_FN MediumStep sampleMediumDistance(const Medium& m, float tMax, float uChannel, float uDistance) {
  const Vec3 sigmaT = mediumSigmaT(m);
  const float channels[3] = {sigmaT.x, sigmaT.y, sigmaT.z};
  const float chosen = channels[uChannel < 1.0f / 3.0f ? 0 : uChannel < 2.0f / 3.0f ? 1 : 2];
  MediumStep step;
  const float t = chosen > 0.0f ? -logf(1.0f - uDistance) / chosen : kInf;
  if (t < tMax) {
    const Vec3 transmittance = mediumTransmittance(m, t);
    const float pdf = meanCollisionDensity(sigmaT, transmittance);
    if (!(pdf > 0.0f)) return step;  // weight 0: the path ends
    step.scattered = true;
    step.t = t;
    step.weight = transmittance * m.sigmaS / pdf;
    step.emission = transmittance * m.sigmaA * m.emission / pdf;
    return step;
  }
  const Vec3 transmittance = mediumTransmittance(m, tMax);
  const float pass = meanPassProbability(transmittance);
  step.t = tMax;
  if (pass > 0.0f) step.weight = transmittance / pass;
  return step;
}

}  // namespace candela
