#pragma once
#include <cstdint>
#include <cstring>

#include "core/platform.h"

namespace candela {

// e^x for x <= 0 with a relative error below 3e-7, in plain arithmetic that compilers vectorise and that gives
// the same result on the host and the device (the filters' CPU and CUDA versions must agree). Arguments below
// -87 (and NaN) give e^-87, which is zero for any weight it multiplies.
CANDELA_FN float fastExpNonPositive(float x) {
  x = fmaxf(x, -87.0f);
  // x = n ln 2 + r with n = floor(x / ln 2), r in [0, ln 2); ln 2 in two parts keeps r exact (Cody and Waite).
  int32_t n = int32_t(x * 1.44269504f);
  n -= float(n) > x * 1.44269504f ? 1 : 0;
  const float r = (x - float(n) * 0.693145751953125f) - float(n) * 1.42860677e-6f;
  // e^r on [0, ln 2]: 1 + r q(r), q through the Chebyshev nodes, relative error 6e-9.
  float p = 1.8770873e-3f;
  p = p * r + 7.9324702e-3f;
  p = p * r + 4.1814245e-2f;
  p = p * r + 1.6664238e-1f;
  p = p * r + 5.0000143e-1f;
  p = p * r + 1.0f;
  p = p * r + 1.0f;
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
