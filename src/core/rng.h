#pragma once
#include <cstdint>

#include "core/platform.h"

namespace candela {

// pcg4d (Jarzynski and Olano 2020, "Hash Functions for GPU Rendering"): a 4D -> 4D integer hash with
// good avalanche behaviour, cheap enough to call once per random number.
struct Uint4 {
  uint32_t x, y, z, w;
};

CANDELA_FN Uint4 pcg4d(Uint4 v) {
  v = {v.x * 1664525u + 1013904223u, v.y * 1664525u + 1013904223u, v.z * 1664525u + 1013904223u,
       v.w * 1664525u + 1013904223u};
  v.x += v.y * v.w;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  v.w += v.y * v.z;
  v = {v.x ^ (v.x >> 16), v.y ^ (v.y >> 16), v.z ^ (v.z >> 16), v.w ^ (v.w >> 16)};
  v.x += v.y * v.w;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  v.w += v.y * v.z;
  return v;
}

// Maps 32 random bits to [0, 1) using the top 24 bits, so 1.0f is never returned.
CANDELA_FN float bitsToUnitFloat(uint32_t bits) { return float(bits >> 8) * (1.0f / 16777216.0f); }

// The random number for (pixel, sample index, dimension, seed). Being a pure function, the CPU and GPU
// backends draw the same sequence, and accumulation can resume at any sample index.
CANDELA_FN float randomUniform(uint32_t pixel, uint32_t sampleIndex, uint32_t dimension, uint32_t seed) {
  return bitsToUnitFloat(pcg4d({pixel, sampleIndex, dimension, seed}).x);
}

}  // namespace candela
