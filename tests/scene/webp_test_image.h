#pragma once
#include <webp/encode.h>

#include <cstdint>
#include <vector>

namespace candela::test {

// A lossless WebP of `width` x `height` RGBA pixels (rows top to bottom), encoded by libwebp.
inline std::vector<uint8_t> losslessWebp(const std::vector<uint8_t>& rgba, int width, int height) {
  uint8_t* encoded = nullptr;
  const size_t size = WebPEncodeLosslessRGBA(rgba.data(), width, height, width * 4, &encoded);
  std::vector<uint8_t> bytes(encoded, encoded + size);
  WebPFree(encoded);
  return bytes;
}

}  // namespace candela::test
