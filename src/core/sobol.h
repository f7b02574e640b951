#pragma once
#include <cstdint>

#include "core/platform.h"

namespace candela {

CANDELA_FN uint32_t reverseBits(uint32_t v) {
#if defined(__CUDA_ARCH__)
  return __brev(v);
#else
  v = ((v >> 1) & 0x55555555u) | ((v & 0x55555555u) << 1);
  v = ((v >> 2) & 0x33333333u) | ((v & 0x33333333u) << 2);
  v = ((v >> 4) & 0x0F0F0F0Fu) | ((v & 0x0F0F0F0Fu) << 4);
  v = ((v >> 8) & 0x00FF00FFu) | ((v & 0x00FF00FFu) << 8);
  return (v >> 16) | (v << 16);
#endif
}

// The first two dimensions of the Sobol sequence as 32-bit fractions. Together they are a (0,2)-sequence:
// every aligned block of 2^m consecutive points has exactly one point in each elementary interval of area 2^-m.
CANDELA_FN uint32_t sobolDimension0(uint32_t index) { return reverseBits(index); }

// Its generator matrix is Pascal's triangle mod 2: output bit j (from the top) is the parity of the index bits k
// with C(k, j) odd, that is (Lucas) of the bits k whose positions contain j's bits. That superset parity over the
// five bits of a position is five shift-xor steps, as in a zeta transform, instead of a loop over the index bits.
CANDELA_FN uint32_t sobolDimension1(uint32_t index) {
  uint32_t z = index;
  z ^= (z >> 1) & 0x55555555u;
  z ^= (z >> 2) & 0x33333333u;
  z ^= (z >> 4) & 0x0F0F0F0Fu;
  z ^= (z >> 8) & 0x00FF00FFu;
  z ^= (z >> 16) & 0x0000FFFFu;
  return reverseBits(z);
}

// Hash-based Owen scrambling (Burley 2020, "Practical Hash-based Owen Scrambling", after Laine and Karras 2011):
// each bit is flipped by a hash of the bits above it, so values that share their leading bits still share them
// afterwards and every net property survives. Different seeds give independent randomisations.
CANDELA_FN uint32_t owenScramble(uint32_t v, uint32_t seed) {
  v = reverseBits(v);
  v += seed;
  v ^= v * 0x6c50b47cu;
  v ^= v * 0xb82f1e52u;
  v ^= v * 0xc7afe638u;
  v ^= v * 0x8d22f6e6u;
  return reverseBits(v);
}

}  // namespace candela
