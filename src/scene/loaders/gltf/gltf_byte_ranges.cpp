#include "scene/loaders/gltf/gltf_byte_ranges.h"

#include <nlohmann/json.hpp>

#include <optional>

#include "io/load_diagnostics.h"
#include "scene/loaders/gltf/gltf_glb.h"

namespace candela {

namespace {

using nlohmann::json;

std::string compact(const json& value) { return value.dump(-1, ' ', false, json::error_handler_t::replace); }

// A whole number of bytes from 0 (the value of `name` in `object`, 0 when absent).
uint64_t byteCount(const json& object, const char* name, const std::string& where, const std::string& file) {
  auto it = object.find(name);
  if (it == object.end()) return 0;
  if (it->is_number_unsigned()) return it->get<uint64_t>();
  failLoad(file, where + "." + name + ": " + compact(*it) + " is not a whole number of bytes from 0");
}

// `offset` and `length` within the byteLength of buffers[buffer], where that buffer exists (else tinygltf names it).
void checkWithinBuffer(const json& buffers, const json& buffer, uint64_t offset, uint64_t length,
                       const std::string& where, const std::string& file) {
  if (!buffer.is_number_unsigned() || buffer.get<uint64_t>() >= buffers.size() ||
      !buffers[buffer.get<size_t>()].is_object())
    return;
  const std::string name = "buffers[" + compact(buffer) + "]";
  const uint64_t available = byteCount(buffers[buffer.get<size_t>()], "byteLength", name, file);
  if (offset > available || length > available - offset)
    failLoad(file, where + ": byteOffset " + std::to_string(offset) + " and byteLength " + std::to_string(length) +
                       " reach beyond the " + std::to_string(available) + " bytes of " + name);
}

// tinygltf keeps the numbers of an extension as 32-bit integers, so a larger one would silently become another.
constexpr uint64_t kMaxExtensionNumber = 2147483647;

// A bufferView's extension (EXT_meshopt_compression's compressed stream) naming a range of a buffer.
void checkExtensionRange(const json& extension, const json& buffers, const std::string& where,
                         const std::string& file) {
  for (const char* name : {"buffer", "byteOffset", "byteLength", "byteStride", "count"}) {
    auto it = extension.find(name);
    if (it != extension.end() && it->is_number() && !(it->is_number_unsigned() && *it <= kMaxExtensionNumber))
      failLoad(file, where + "." + name + ": " + compact(*it) + " is not a whole number from 0 to " +
                         std::to_string(kMaxExtensionNumber));
  }
  auto buffer = extension.find("buffer");
  if (buffer != extension.end())
    checkWithinBuffer(buffers, *buffer, byteCount(extension, "byteOffset", where, file),
                      byteCount(extension, "byteLength", where, file), where, file);
}

const json* arrayOf(const json& doc, const char* name) {
  auto it = doc.find(name);
  return it != doc.end() && it->is_array() ? &*it : nullptr;
}

}  // namespace

void checkGltfByteRanges(const uint8_t* data, size_t size, const std::string& file) {
  const std::optional<GltfJson> parsed = gltfJsonMentioning(data, size, "byteOffset");
  if (!parsed) return;
  const json& doc = parsed->doc;
  const json* buffers = arrayOf(doc, "buffers");
  if (const json* views = arrayOf(doc, "bufferViews"))
    for (size_t i = 0; i < views->size(); ++i) {
      const json& view = (*views)[i];
      if (!view.is_object()) continue;
      const std::string where = "bufferViews[" + std::to_string(i) + "]";
      const uint64_t offset = byteCount(view, "byteOffset", where, file);
      const uint64_t length = byteCount(view, "byteLength", where, file);
      auto extensions = view.find("extensions");
      if (extensions != view.end() && extensions->is_object())
        for (const auto& [name, extension] : extensions->items())
          if (extension.is_object())
            checkExtensionRange(extension, buffers ? *buffers : json::array(), where + ".extensions." + name, file);
      auto buffer = view.find("buffer");
      if (buffers && buffer != view.end()) checkWithinBuffer(*buffers, *buffer, offset, length, where, file);
    }
  if (const json* accessors = arrayOf(doc, "accessors"))
    for (size_t i = 0; i < accessors->size(); ++i) {
      const json& accessor = (*accessors)[i];
      if (!accessor.is_object()) continue;
      const std::string where = "accessors[" + std::to_string(i) + "]";
      byteCount(accessor, "byteOffset", where, file);
      auto sparse = accessor.find("sparse");
      if (sparse == accessor.end() || !sparse->is_object()) continue;
      for (const char* part : {"indices", "values"}) {
        auto it = sparse->find(part);
        if (it != sparse->end() && it->is_object())
          byteCount(*it, "byteOffset", where + ".sparse." + std::string(part), file);
      }
    }
}

}  // namespace candela
