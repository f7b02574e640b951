#pragma once
// Free-flight sampling and transmittance in a grid medium (medium_grid.h), against its majorant grid
// (majorant_walk.h), as pbrt-v4's SampleT_maj and VolPathIntegrator do it:
//
// - Distance sampling is delta tracking with null collisions: tentative collisions are drawn from the
//   piecewise-constant grey majorant, and each is real with probability P = mean(sigma_t) / majorant, null with
//   1 - P. That choice is the homogeneous path's channel MIS (distance_sampling.h) applied to every collision:
//   one channel chosen uniformly, real with probability sigma_t[c] / majorant, weighed by the balance heuristic
//   over the three channels, which is the same as choosing with the channels' mean. A real collision weighs the
//   throughput by sigma_s / (majorant P) and adds sigma_a Le / (majorant P); a null one by
//   (majorant - sigma_t) / (majorant (1 - P)): each channel is estimated without bias, and a grey medium's
//   weights are exactly 1, as in classic delta tracking.
// - Shadow rays use ratio tracking: the product over tentative collisions of 1 - sigma_t / majorant, with
//   Russian roulette once every channel is below 0.05, as pbrt's TraceTransmittance.
//
// The numbers: distance sampling takes the segment's two numbers from the path's sampler (as a homogeneous
// medium does), the first tentative collision from one of them and every later choice from a hash seeded with
// both (pbrt seeds its RNG from two sampler values likewise). Ratio tracking draws none from the sampler: its hash
// is seeded with the shadow ray's origin and direction, as pbrt's is.
#include "core/rng.h"
#include "kernel/interaction.h"
#include "kernel/media/distance_sampling.h"
#include "kernel/media/majorant_walk.h"

namespace candela {

// Independent numbers in [0, 1) from a seed of two words.
class TrackingRandom {
 public:
  CANDELA_FN TrackingRandom(uint32_t seed0, uint32_t seed1) : seed0_(seed0), seed1_(seed1) {}
  CANDELA_FN float next() { return bitsToUnitFloat(pcg4d({seed0_, seed1_, count_++, 0x6d656469u}).x); }

 private:
  uint32_t seed0_, seed1_, count_ = 0;
};

CANDELA_FN float meanComponent(Vec3 v) { return (v.x + v.y + v.z) * (1.0f / 3.0f); }

// Samples where a ray (world space) in grid medium m, whose segment ends at tMax (infinite where it escapes),
// first collides for real; the result reads as distance_sampling.h's. Called, not inlined, on the device, as is
// gridMediumTransmittance: the media path tracks at every segment of the path and of its shadow rays.
CANDELA_FN_CALLED MediumStep sampleGridMediumDistance(const Medium& m, const MediumGrid& grid, const float* values,
                                                      const Ray& ray, float tMax, float uSeed, float uDistance) {
  MediumStep step;
  step.t = tMax;
  step.weight = {1, 1, 1};
  MajorantWalk walk(grid, values, ray, tMax);
  TrackingRandom random(uint32_t(floatAsInt(uSeed)), uint32_t(floatAsInt(uDistance)));
  float opticalDepth = -logf(1.0f - uDistance);  // majorant x distance left to the next tentative collision
  Vec3 weight{1, 1, 1};
  MajorantSegment segment;
  while (walk.next(segment)) {
    if (!(segment.majorant > 0.0f)) continue;
    float t = segment.tMin;
    for (;;) {
      const float toCollision = opticalDepth / segment.majorant;
      if (t + toCollision >= segment.tMax) {
        opticalDepth -= (segment.tMax - t) * segment.majorant;
        break;
      }
      t += toCollision;
      const MediumPoint point = gridMediumAt(m, grid, values, ray.origin + ray.direction * t);
      const Vec3 sigmaT = point.sigmaA + point.sigmaS;
      const float pReal = fminf(meanComponent(sigmaT) / segment.majorant, 1.0f);
      if (random.next() < pReal) {
        const float density = segment.majorant * pReal;
        step.scattered = true;
        step.t = t;
        step.weight = weight * point.sigmaS / density;
        step.emission = weight * point.sigmaA * point.emission / density;
        return step;
      }
      const Vec3 sigmaN = Vec3{fmaxf(segment.majorant - sigmaT.x, 0.0f), fmaxf(segment.majorant - sigmaT.y, 0.0f),
                               fmaxf(segment.majorant - sigmaT.z, 0.0f)};
      weight *= sigmaN / (segment.majorant * (1.0f - pReal));
      if (isBlack(weight)) {
        step.weight = {};
        return step;
      }
      opticalDepth = -logf(1.0f - random.next());
    }
  }
  step.weight = weight;
  return step;
}

// The transmittance of grid medium m along a ray (world space) from 0 to tMax, by ratio tracking: an unbiased
// estimate per channel.
CANDELA_FN_CALLED Vec3 gridMediumTransmittance(const Medium& m, const MediumGrid& grid, const float* values,
                                               const Ray& ray, float tMax) {
  MajorantWalk walk(grid, values, ray, tMax);
  auto bits = [](float f) { return uint32_t(floatAsInt(f)); };
  const Uint4 h = pcg4d({bits(ray.origin.x), bits(ray.origin.y), bits(ray.origin.z), bits(ray.direction.x)});
  TrackingRandom random(h.x, pcg4d({h.y ^ bits(ray.direction.y), h.z ^ bits(ray.direction.z), h.w, 0}).x);
  Vec3 transmittance{1, 1, 1};
  MajorantSegment segment;
  while (walk.next(segment)) {
    if (!(segment.majorant > 0.0f)) continue;
    float t = segment.tMin;
    for (;;) {
      t += -logf(1.0f - random.next()) / segment.majorant;
      if (t >= segment.tMax) break;
      const MediumPoint point = gridMediumAt(m, grid, values, ray.origin + ray.direction * t);
      const Vec3 ratio = Vec3{1, 1, 1} - (point.sigmaA + point.sigmaS) / segment.majorant;
      transmittance *= Vec3{fmaxf(ratio.x, 0.0f), fmaxf(ratio.y, 0.0f), fmaxf(ratio.z, 0.0f)};
      if (maxComponent(transmittance) < 0.05f) {
        if (random.next() < 0.75f) return {};
        transmittance = transmittance / 0.25f;
      }
    }
  }
  return transmittance;
}

}  // namespace candela
