#pragma once
#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace candela {

// The JSON of a .gltf, or of a .glb's JSON chunk (`jsonLength` bytes from byte 20), parsed: what the loader's
// passes that rewrite a file's JSON before tinygltf reads it (gltf_draco.h, gltf_meshopt.h) change.
struct GltfJson {
  nlohmann::json doc;
  bool glb = false;
  size_t jsonLength = 0;
};

// The file's JSON when its text mentions `extension` and parses as an object; nothing otherwise, which leaves the
// file as it is for tinygltf (and its errors).
std::optional<GltfJson> gltfJsonMentioning(const uint8_t* data, size_t size, std::string_view extension);

// The bytes of the file with its JSON replaced by `json.doc` (a .glb's other chunks kept as they are).
std::vector<uint8_t> withRewrittenJson(const uint8_t* data, size_t size, const GltfJson& json);

}  // namespace candela
