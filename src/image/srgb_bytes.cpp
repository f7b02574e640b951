#include "image/srgb_bytes.h"

#include <limits>
#include <memory>
#include <stdexcept>

#include "image/tonemap.h"

namespace candela {

namespace {

float floatOfBits(uint32_t bits) {
  float f;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}

uint8_t exactByte(uint32_t bits) { return displayByte(linearToSrgb(floatOfBits(bits))); }

// The representation of the smallest t in [0, 1] whose byte is at least `byte`, by bisection over the
// representations, which order the non-negative floats as the floats themselves.
uint32_t thresholdBits(uint8_t byte) {
  uint32_t below = 0, atOrAbove = SrgbByteTable::kOneBits;  // exactByte(below) < byte <= exactByte(atOrAbove)
  while (atOrAbove - below > 1) {
    const uint32_t middle = below + (atOrAbove - below) / 2;
    (exactByte(middle) >= byte ? atOrAbove : below) = middle;
  }
  return atOrAbove;
}

std::unique_ptr<SrgbByteTable> makeTable() {
  auto table = std::make_unique<SrgbByteTable>();
  uint32_t bits[257];
  bits[0] = 0;
  for (int b = 1; b < 256; ++b) bits[b] = thresholdBits(uint8_t(b));
  for (int b = 0; b < 256; ++b) table->threshold[b] = floatOfBits(bits[b]);
  table->threshold[256] = std::numeric_limits<float>::infinity();
  uint8_t byte = 0;
  for (uint32_t bucket = 0; bucket < SrgbByteTable::kBuckets; ++bucket) {
    const uint32_t first = bucket << SrgbByteTable::kBucketShift;
    const uint64_t end = uint64_t(first) + (1u << SrgbByteTable::kBucketShift);  // past the bucket's last float
    while (byte < 255 && bits[byte + 1] <= first) ++byte;
    table->bucketByte[bucket] = byte;
    if (byte < 254 && bits[byte + 2] < end)
      throw std::logic_error("the sRGB byte table has two thresholds in one bucket");
  }
  return table;
}

}  // namespace

const SrgbByteTable& srgbByteTable() {
  static const std::unique_ptr<SrgbByteTable> table = makeTable();
  return *table;
}

}  // namespace candela
