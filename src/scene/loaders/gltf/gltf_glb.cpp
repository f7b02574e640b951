#include "scene/loaders/gltf/gltf_glb.h"

#include <cstring>
#include <string>

namespace candela {

std::optional<GltfJson> gltfJsonMentioning(const uint8_t* data, size_t size, std::string_view extension) {
  GltfJson json;
  json.glb = size >= 20 && std::memcmp(data, "glTF", 4) == 0;
  json.jsonLength = size;
  if (json.glb) {
    uint32_t length;
    std::memcpy(&length, data + 12, 4);
    if (length > size - 20) return std::nullopt;
    json.jsonLength = length;
  }
  const char* text = reinterpret_cast<const char*>(data) + (json.glb ? 20 : 0);
  if (std::string_view(text, json.jsonLength).find(extension) == std::string_view::npos) return std::nullopt;
  json.doc = nlohmann::json::parse(text, text + json.jsonLength, nullptr, false);
  if (!json.doc.is_object()) return std::nullopt;
  return json;
}

std::vector<uint8_t> withRewrittenJson(const uint8_t* data, size_t size, const GltfJson& json) {
  std::string text = json.doc.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  if (!json.glb) return std::vector<uint8_t>(text.begin(), text.end());
  text.resize((text.size() + 3) / 4 * 4, ' ');  // chunks are padded to 4 bytes, JSON with spaces
  const size_t restAt = 20 + json.jsonLength;
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
