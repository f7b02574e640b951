#pragma once
#include <cstdint>
#include <cstring>

#include "core/platform.h"

namespace candela {

// e^x for x <= 0 with a relative error below 3e-7, in plain arithmetic that compilers vectorise and that gives
// the same result on the host and the device (the filters' CPU and CUDA versions must agree). Arguments below
// -87 (and NaN) give e^-87, which is zero for any weight it multiplies.
CANDELA_FN float fastExpNonPositive(float x) {
  // Clamps to -87 on the bit pattern: below -87 (and NaN) a negative float's bits are larger. Unlike a float
  // comparison, an integer one lets compilers vectorise the callers' loops.
  constexpr uint32_t kMinusEightySeven = 0xC2AE0000u;
#if defined(__CUDA_ARCH__)
  const uint32_t xBits = __float_as_uint(x);
  x = __uint_as_float(xBits < kMinusEightySeven ? xBits : kMinusEightySeven);
#else
  uint32_t xBits;
  std::memcpy(&xBits, &x, sizeof xBits);
  xBits = xBits < kMinusEightySeven ? xBits : kMinusEightySeven;
  std::memcpy(&x, &xBits, sizeof x);
#endif
  // x = n ln 2 + r with n the integer nearest x / ln 2, so r in [-ln 2 / 2, ln 2 / 2]; ln 2 in two parts keeps r
  // exact (Cody and Waite). Adding 1.5 * 2^23 rounds x / ln 2 to an integer, which lands in the sum's low bits.
  constexpr float kRoundingShift = 12582912.0f;
  constexpr int32_t kRoundingShiftBits = 0x4B400000;
  const float shifted = x * 1.44269504f + kRoundingShift;
#if defined(__CUDA_ARCH__)
  const int32_t n = __float_as_int(shifted) - kRoundingShiftBits;
#else
  int32_t shiftedBits;
  std::memcpy(&shiftedBits, &shifted, sizeof shiftedBits);
  const int32_t n = shiftedBits - kRoundingShiftBits;
#endif
  const float r = (x - float(n) * 0.693145751953125f) - float(n) * 1.42860677e-6f;
  // e^r = 1 + r + r^2 q(r), q fitted to the relative error of e^r over r's interval (Lawson's algorithm), relative
  // error 2e-7. Estrin's scheme: its products are independent, so the chain of dependent operations is short and
  // vectorised loops that call this keep more iterations in flight than Horner's scheme allows.
  const float r2 = r * r;
  const float q = (4.99992311e-1f + 1.66671142e-1f * r) + r2 * (4.18901481e-2f + 8.31254199e-3f * r);
  const float p = (1.0f + r) + r2 * q;
  const int32_t bits = (n + 127) << 23;
#if defined(__CUDA_ARCH__)
  return p * __int_as_float(bits);
#else
  float scale;
  std::memcpy(&scale, &bits, sizeof scale);
  return p * scale;
#endif
}

}  // namespace candela
