#pragma once
#include <cstdint>

#include "core/platform.h"

namespace candela {

#if !defined(__CUDA_ARCH__)
// Each byte with its bits in reverse order: the host has no bit-reversal instruction, and four lookups take fewer
// operations than the five shift-mask steps that reverse a word (docs/performance.md, 'Samplers').
struct ReversedBytes {
  uint8_t of[256] = {};
  constexpr ReversedBytes() {
    for (uint32_t b = 0; b < 256; ++b)
      for (uint32_t bit = 0; bit < 8; ++bit)
        if (b & (1u << bit)) of[b] = uint8_t(of[b] | (0x80u >> bit));
  }
};
inline constexpr ReversedBytes kReversedBytes{};
#endif

CANDELA_FN uint32_t reverseBits(uint32_t v) {
#if defined(__CUDA_ARCH__)
  return __brev(v);
#else
  return uint32_t(kReversedBytes.of[v & 0xFFu]) << 24 | uint32_t(kReversedBytes.of[(v >> 8) & 0xFFu]) << 16 |
         uint32_t(kReversedBytes.of[(v >> 16) & 0xFFu]) << 8 | uint32_t(kReversedBytes.of[v >> 24]);
#endif
}

// reverseBits(v) >> 8: the 24 bits that bitsToUnitFloat keeps, one table lookup fewer on the host.
CANDELA_FN uint32_t reverseBitsHigh24(uint32_t v) {
#if defined(__CUDA_ARCH__)
  return __brev(v) >> 8;
#else
  return uint32_t(kReversedBytes.of[v & 0xFFu]) << 16 | uint32_t(kReversedBytes.of[(v >> 8) & 0xFFu]) << 8 |
         uint32_t(kReversedBytes.of[(v >> 16) & 0xFFu]);
#endif
}

// The first two dimensions of the Sobol sequence as 32-bit fractions. Together they are a (0,2)-sequence:
// every aligned block of 2^m consecutive points has exactly one point in each elementary interval of area 2^-m.
CANDELA_FN uint32_t sobolDimension0(uint32_t index) { return reverseBits(index); }

// The second dimension with its bits reversed (bit j from the bottom is output bit j from the top). Its generator
// matrix is Pascal's triangle mod 2: output bit j (from the top) is the parity of the index bits k with C(k, j) odd,
// that is (Lucas) of the bits k whose positions contain j's bits. That superset parity over the five bits of a
// position is five shift-xor steps, as in a zeta transform, instead of a loop over the index bits.
CANDELA_FN uint32_t sobolDimension1Reversed(uint32_t index) {
  uint32_t z = index;
  z ^= (z >> 1) & 0x55555555u;
  z ^= (z >> 2) & 0x33333333u;
  z ^= (z >> 4) & 0x0F0F0F0Fu;
  z ^= (z >> 8) & 0x00FF00FFu;
  z ^= (z >> 16) & 0x0000FFFFu;
  return z;
}

CANDELA_FN uint32_t sobolDimension1(uint32_t index) { return reverseBits(sobolDimension1Reversed(index)); }

// Hash-based Owen scrambling (Burley 2020, "Practical Hash-based Owen Scrambling", after Laine and Karras 2011):
// each bit is flipped by a hash of the bits above it, so values that share their leading bits still share them
// afterwards and every net property survives. Different seeds give independent randomisations. owenHash works on
// the value with its bits reversed (a product's low bits depend on no higher ones); owenScramble reverses around it.
CANDELA_FN uint32_t owenHash(uint32_t reversed, uint32_t seed) {
  uint32_t v = reversed + seed;
  v ^= v * 0x6c50b47cu;
  v ^= v * 0xb82f1e52u;
  v ^= v * 0xc7afe638u;
  v ^= v * 0x8d22f6e6u;
  return v;
}

CANDELA_FN uint32_t owenScramble(uint32_t v, uint32_t seed) { return reverseBits(owenHash(reverseBits(v), seed)); }

}  // namespace candela
