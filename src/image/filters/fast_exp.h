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
  // x = n ln 2 + r with n = floor(x / ln 2), r in [0, ln 2); ln 2 in two parts keeps r exact (Cody and Waite).
  const float t = x * 1.44269504f;
  int32_t n = int32_t(t);
  n -= float(n) > t ? 1 : 0;
  const float r = (x - float(n) * 0.693145751953125f) - float(n) * 1.42860677e-6f;
  // e^r on [0, ln 2] = 1 + r + r^2 q(r), q through the Chebyshev nodes, relative error 6e-9. Estrin's scheme: its
  // products are independent, so the chain of dependent operations is short and vectorised loops that call this keep
  // more iterations in flight than Horner's scheme allows.
  const float r2 = r * r;
  const float q =
      (5.0000143e-1f + 1.6664238e-1f * r) + r2 * (4.1814245e-2f + 7.9324702e-3f * r) + (r2 * r2) * 1.8770873e-3f;
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
