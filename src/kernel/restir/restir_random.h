#pragma once
// ReSTIR's own random numbers, apart from the path's (whose numbers stay those of RestirMode::Off): white noise, one
// stream per pixel (or presampled light), sample index and pass.
#include <cstdint>

#include "core/math.h"
#include "core/rng.h"

namespace candela {

// A stream seeded by one pcg4d hash and then stepped as PCG's 32-bit generator (O'Neill 2014, PCG-RXS-M-XS: an LCG
// whose state is permuted into each output), the hash's second word choosing the LCG's increment: one multiply-add
// and a few shifts per number, where a hash per number (PathSampler's independent kind) cost ReSTIR a tenth of its
// time on the CPU.
class RestirRandom {
 public:
  CANDELA_FN RestirRandom(uint32_t stream, uint32_t sampleIndex, uint32_t seed, uint32_t pass) {
    const Uint4 h = pcg4d({stream, sampleIndex, seed, 0x9E3779B9u * (pass + 1u)});
    state_ = h.x;
    increment_ = h.y | 1u;
  }

  CANDELA_FN uint32_t nextBits() {
    state_ = state_ * 747796405u + increment_;
    const uint32_t word = ((state_ >> ((state_ >> 28u) + 4u)) ^ state_) * 277803737u;
    return (word >> 22u) ^ word;
  }
  CANDELA_FN float next1D() { return bitsToUnitFloat(nextBits()); }
  CANDELA_FN Vec2 next2D() {
    const float u = next1D();
    return {u, next1D()};
  }

 private:
  uint32_t state_ = 0;
  uint32_t increment_ = 1;
};

// The passes whose decisions draw from RestirRandom streams.
enum class RestirPass : uint32_t { Candidates, Shade, Presample };

}  // namespace candela
