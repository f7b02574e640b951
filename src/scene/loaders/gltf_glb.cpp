#include "scene/loaders/gltf_glb.h"

#include <cstring>

namespace candela {

std::vector<uint8_t> replaceGlbJson(const uint8_t* data, size_t size, size_t jsonLength, std::string text) {
  text.resize((text.size() + 3) / 4 * 4, ' ');  // chunks are padded to 4 bytes, JSON with spaces
  const size_t restAt = 20 + jsonLength;
  const size_t total = 20 + text.size() + (size - restAt);
  std::vector<uint8_t> out(total);
  std::memcpy(out.data(), data, 20);
  const uint32_t total32 = uint32_t(total), length32 = uint32_t(text.size());
  std::memcpy(out.data() + 8, &total32, 4);
  std::memcpy(out.data() + 12, &length32, 4);
  std::memcpy(out.data() + 20, text.data(), text.size());
  std::memcpy(out.data() + 20 + text.size(), data + restAt, size - restAt);
  return out;
}

}  // namespace candela
