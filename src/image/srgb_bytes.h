#pragma once
// The 8-bit sRGB byte of a display value by table: displayByte(linearToSrgb(t)) (image/tonemap.h) without its
// powf, for the display frames of image/display_kernel.h. The CPU and CUDA versions look up the same table, so
// they give the same bytes.
#include <cstdint>
#include <cstring>

#include "core/platform.h"

namespace candela {

// The byte is a non-decreasing function of t in [0, 1], so it is the count of the thresholds t has reached. The
// table splits [0, 1] by the high bits of t's float representation into buckets, narrower everywhere than the gap
// between two thresholds, and holds the byte at each bucket's smallest float: a bucket holds at most one
// threshold, and one comparison with the next threshold finishes the look-up.
struct SrgbByteTable {
  static constexpr int kBucketShift = 14;
  static constexpr uint32_t kOneBits = 0x3F800000u;  // 1.0f
  static constexpr uint32_t kBuckets = (kOneBits >> kBucketShift) + 1;

  uint8_t bucketByte[kBuckets];
  // threshold[b]: the smallest t whose byte is b, for b in [1, 255]; threshold[0] = 0 and threshold[256] is
  // infinite, so that the look-up needs no test of its bounds.
  float threshold[257];
};

// The table, made at the first call; it checks that no bucket holds two thresholds (std::logic_error otherwise).
const SrgbByteTable& srgbByteTable();

// displayByte(linearToSrgb(t)) for t in [0, 1] (not NaN; display_kernel.h's displayValue gives such values).
CANDELA_FN uint8_t srgbByte(const SrgbByteTable& table, float t) {
  uint32_t bits;
#if defined(__CUDA_ARCH__)
  bits = __float_as_uint(t);
#else
  std::memcpy(&bits, &t, sizeof bits);
#endif
  const uint8_t below = table.bucketByte[bits >> SrgbByteTable::kBucketShift];
  return uint8_t(below + (t >= table.threshold[below + 1] ? 1 : 0));
}

}  // namespace candela
