#include "scene/loaders/gltf/gltf_meshopt.h"

#ifdef CANDELA_HAS_MESHOPT
#include <meshoptimizer.h>
#endif
#include <nlohmann/json.hpp>

#include <string_view>
#include <vector>

#include "io/load_diagnostics.h"
#include "scene/loaders/gltf/gltf_glb.h"

namespace candela {

namespace {

constexpr std::string_view kExtension = "EXT_meshopt_compression";
// The vertex codec stores a block of 16 vertices of zeros in a few bits per byte; no valid stream expands by more
// than this. A larger claim is forged, and is refused before the memory is taken.
constexpr size_t kMaxExpansion = 256;

}  // namespace

bool gltfMeshoptAvailable() {
#ifdef CANDELA_HAS_MESHOPT
  return true;
#else
  return false;
#endif
}

std::optional<std::vector<uint8_t>> withMeshoptPlaceholderBuffers(const uint8_t* data, size_t size) {
  if (!gltfMeshoptAvailable()) return std::nullopt;
  std::optional<GltfJson> json = gltfJsonMentioning(data, size, kExtension);
  if (!json || !json->doc.contains("buffers") || !json->doc["buffers"].is_array()) return std::nullopt;
  nlohmann::json& doc = json->doc;
  const bool glb = json->glb;
  // The buffers that compressed bufferViews decode into; not every file marks them with the extension.
  std::vector<bool> decodedInto(doc["buffers"].size(), false);
  if (doc.contains("bufferViews") && doc["bufferViews"].is_array())
    for (const nlohmann::json& view : doc["bufferViews"]) {
      if (!view.is_object() || !view.contains("extensions") || !view["extensions"].is_object() ||
          !view["extensions"].contains(kExtension) || !view.contains("buffer") || !view["buffer"].is_number_unsigned())
        continue;
      const size_t buffer = view["buffer"].get<size_t>();
      if (buffer < decodedInto.size()) decodedInto[buffer] = true;
    }
  bool changed = false;
  for (size_t i = 0; i < doc["buffers"].size(); ++i) {
    nlohmann::json& buffer = doc["buffers"][i];
    if (!buffer.is_object() || buffer.contains("uri") || (glb && i == 0)) continue;  // a .glb's buffer 0: its BIN
    auto extensions = buffer.find("extensions");
    const bool marked = extensions != buffer.end() && extensions->is_object() && extensions->contains(kExtension);
    if (!marked && !decodedInto[i]) continue;
    buffer["uri"] = "data:application/octet-stream;base64,AAAA";
    buffer["byteLength"] = 3;
    changed = true;
  }
  if (!changed) return std::nullopt;
  return withRewrittenJson(data, size, *json);
}

#ifndef CANDELA_HAS_MESHOPT

void decodeMeshoptBufferViews(tinygltf::Model&, const std::string&) {}

#else

namespace {

// The extension's integer property `name`, or `fallback` when it is absent; -1 when it is not a usable number.
int64_t integer(const tinygltf::Value& e, const char* name, int64_t fallback) {
  if (!e.Has(name)) return fallback;
  const tinygltf::Value& v = e.Get(name);
  if (!v.IsNumber()) return -1;
  const double d = v.GetNumberAsDouble();
  return d >= 0.0 && d <= 9.0e15 && d == double(int64_t(d)) ? int64_t(d) : -1;
}

std::string text(const tinygltf::Value& e, const char* name, const char* fallback) {
  return e.Has(name) && e.Get(name).IsString() ? e.Get(name).Get<std::string>() : std::string(fallback);
}

void decodeBufferView(tinygltf::Model& model, size_t index, const tinygltf::Value& e, const std::string& file) {
  const std::string where = "bufferViews[" + std::to_string(index) + "].extensions." + std::string(kExtension);
  auto fail = [&](const std::string& why) { failLoad(file, where + ": " + why); };
  const int64_t buffer = integer(e, "buffer", -1), offset = integer(e, "byteOffset", 0);
  const int64_t length = integer(e, "byteLength", -1), stride = integer(e, "byteStride", -1);
  const int64_t count = integer(e, "count", -1);
  if (buffer < 0 || size_t(buffer) >= model.buffers.size()) fail("'buffer' names no buffer");
  const std::vector<unsigned char>& source = model.buffers[size_t(buffer)].data;
  if (offset < 0 || length < 0 || size_t(offset) > source.size() || size_t(length) > source.size() - size_t(offset))
    fail("'byteOffset' and 'byteLength' reach beyond the buffer");
  if (stride <= 0 || stride > 256 || count < 0) fail("'byteStride' or 'count' is missing or out of range");
  const std::string mode = text(e, "mode", ""), filter = text(e, "filter", "NONE");
  const size_t size = size_t(stride) * size_t(count);
  if (size > size_t(length) * kMaxExpansion + 4096) fail("'count' claims more data than the compressed bytes hold");
  std::vector<unsigned char> decoded(size);
  const unsigned char* compressed = source.data() + offset;
  int status = -1;
  if (mode == "ATTRIBUTES") {
    if (stride % 4 != 0) fail("the byteStride of ATTRIBUTES must be a multiple of 4");
    status = meshopt_decodeVertexBuffer(decoded.data(), size_t(count), size_t(stride), compressed, size_t(length));
  } else if (mode == "TRIANGLES" || mode == "INDICES") {
    if (stride != 2 && stride != 4) fail("the byteStride of " + mode + " must be 2 or 4");
    if (mode == "TRIANGLES" && count % 3 != 0) fail("the count of TRIANGLES must be a multiple of 3");
    status =
        mode == "TRIANGLES"
            ? meshopt_decodeIndexBuffer(decoded.data(), size_t(count), size_t(stride), compressed, size_t(length))
            : meshopt_decodeIndexSequence(decoded.data(), size_t(count), size_t(stride), compressed, size_t(length));
  } else {
    fail("mode '" + mode + "' is not ATTRIBUTES, TRIANGLES or INDICES");
  }
  if (status != 0) fail("the compressed data cannot be decoded");
  if (filter != "NONE" && mode != "ATTRIBUTES") fail("filters apply to ATTRIBUTES only");
  if (filter == "OCTAHEDRAL") {
    if (stride != 4 && stride != 8) fail("the byteStride of the OCTAHEDRAL filter must be 4 or 8");
    meshopt_decodeFilterOct(decoded.data(), size_t(count), size_t(stride));
  } else if (filter == "QUATERNION") {
    if (stride != 8) fail("the byteStride of the QUATERNION filter must be 8");
    meshopt_decodeFilterQuat(decoded.data(), size_t(count), size_t(stride));
  } else if (filter == "EXPONENTIAL") {
    meshopt_decodeFilterExp(decoded.data(), size_t(count), size_t(stride));
  } else if (filter != "NONE") {
    fail("filter '" + filter + "' is not NONE, OCTAHEDRAL, QUATERNION or EXPONENTIAL");
  }
  tinygltf::BufferView& view = model.bufferViews[index];
  view.buffer = int(model.buffers.size());
  view.byteOffset = 0;
  view.byteLength = size;
  if (mode == "ATTRIBUTES") view.byteStride = size_t(stride);
  tinygltf::Buffer out;
  out.data = std::move(decoded);
  model.buffers.push_back(std::move(out));
}

}  // namespace

void decodeMeshoptBufferViews(tinygltf::Model& model, const std::string& file) {
  const std::string name(kExtension);
  for (size_t i = 0; i < model.bufferViews.size(); ++i) {
    auto e = model.bufferViews[i].extensions.find(name);
    if (e != model.bufferViews[i].extensions.end()) decodeBufferView(model, i, e->second, file);
  }
}

#endif

}  // namespace candela
