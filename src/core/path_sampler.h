#pragma once
#include <cstdint>

#include "core/math.h"
#include "core/rng.h"
#include "core/sobol.h"

namespace candela {

enum class SamplerKind : uint32_t {
  // Owen-scrambled Sobol points: each 1D and 2D decision of a path is stratified over a pixel's samples, so
  // error falls faster than 1/sqrt(N) wherever the integrand allows.
  Sobol,
  // pcg4d white noise: every number independent of every other.
  Independent,
};

// Hands out the random numbers of one path sample, a dimension (or a pair of them) at a time. Every number is a
// pure function of (pixel, sample index, dimension, seed, kind), so the CPU and GPU backends draw the same
// sequence and accumulation can resume at any sample index.
//
// Sobol: a pixel's samples of even and of odd index are two sequences of their own, scrambled independently, so
// that the difference of their means measures the variance of the pixel's mean (kernel/film.h, halvesVariance),
// which the sample variance overstates for stratified samples. Within a half, sample index i is point i / 2. The
// dimension (and the seed, pixel and half) hash to three seeds; one Owen-scrambles the point's index (Burley
// 2020), which keeps each aligned block of 2^m indices a block and decorrelates the dimensions, the other two
// Owen-scramble the first two Sobol dimensions at that index. A half's first 2^m samples of any next2D call thus
// form a (0,m,2)-net, and of any next1D call one point in each interval of length 2^-m. Pixels are scrambled
// independently of each other.
class PathSampler {
 public:
  CANDELA_FN PathSampler(uint32_t pixel, uint32_t sampleIndex, uint32_t seed, SamplerKind kind = SamplerKind::Sobol)
      : pixel_(pixel), sampleIndex_(sampleIndex), seed_(seed), kind_(kind) {}

  CANDELA_FN float next1D() {
    uint32_t dimension = dimension_++;
    if (kind_ == SamplerKind::Independent) return randomUniform(pixel_, sampleIndex_, dimension, seed_);
    Uint4 seeds = dimensionSeeds(dimension);
    uint32_t index = owenScramble(sampleIndex_ >> 1, seeds.x);
    return reversedBitsToUnitFloat(owenHash(index, seeds.y));
  }

  CANDELA_FN Vec2 next2D() {
    if (kind_ == SamplerKind::Independent) {
      float u = next1D();
      return {u, next1D()};
    }
    Uint4 seeds = dimensionSeeds(dimension_);
    dimension_ += 2;
    uint32_t index = owenScramble(sampleIndex_ >> 1, seeds.x);
    return {reversedBitsToUnitFloat(owenHash(index, seeds.y)),
            reversedBitsToUnitFloat(owenHash(sobolDimension1Reversed(index), seeds.z))};
  }

  // The next dimension, and the way back to it: a path whose vertices are shaded in separate launches keeps it
  // between them (backends/optix/wavefront_schedule.h).
  CANDELA_FN uint32_t dimension() const { return dimension_; }
  CANDELA_FN void setDimension(uint32_t dimension) { dimension_ = dimension; }

  // The next dimension's 32 random bits, for callers that hash them further (white noise for every kind).
  CANDELA_FN uint32_t nextBits() { return pcg4d({pixel_, sampleIndex_, dimension_++, seed_}).x; }

 private:
  // bitsToUnitFloat(reverseBits(bits)). A Sobol number is owenScramble(sobolDimensionK(index), seed), where
  // owenScramble reverses, hashes and reverses again and sobolDimensionK ends with a reversal: the two reversals in
  // the middle cancel, and of the last one only the 24 bits that reach the float are needed. These are the numbers
  // of the definition (tests/kernel/path_sampler_test.cpp compares them), with two reversals fewer per number.
  CANDELA_FN static float reversedBitsToUnitFloat(uint32_t bits) {
    return float(reverseBitsHigh24(bits)) * (1.0f / 16777216.0f);
  }

  // The Sobol seeds of a dimension in the sample's half; the constant keeps them apart from the white-noise numbers
  // of the same inputs.
  CANDELA_FN Uint4 dimensionSeeds(uint32_t dimension) const {
    return pcg4d({pixel_, dimension, seed_, 0x50B01u + (sampleIndex_ & 1u)});
  }

  uint32_t pixel_;
  uint32_t sampleIndex_;
  uint32_t seed_;
  SamplerKind kind_;
  uint32_t dimension_ = 0;
};

}  // namespace candela
