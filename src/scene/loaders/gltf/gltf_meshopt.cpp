#include "scene/loaders/gltf/gltf_meshopt.h"

#ifdef CANDELA_HAS_MESHOPT
#include <meshoptimizer.h>
#endif
#include <nlohmann/json.hpp>

#include <map>
#include <optional>
#include <set>
#include <string_view>
#include <vector>

#include "io/load_diagnostics.h"
#include "scene/loaders/gltf/gltf_buffer_charge.h"
#include "scene/loaders/gltf/gltf_glb.h"

namespace candela {

namespace {

constexpr std::string_view kExtension = "EXT_meshopt_compression";
// The vertex codec stores a block of 16 vertices of zeros in a few bits per byte; no valid stream expands by more
// than this. A larger claim is forged, and is refused before the memory is taken.
constexpr size_t kMaxExpansion = 256;
// What the distinct streams of a file may decode to beyond kMaxExpansion times the buffers they read from.
constexpr size_t kDecodedSlack = size_t(1) << 20;

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

void decodeMeshoptBufferViews(tinygltf::Model&, const std::string&, GltfBufferCharge&) {}

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

// A compressed stream and how to decode it: bufferViews that agree on all of it decode to the same bytes, which
// are decoded once and shared.
struct Stream {
  size_t buffer = 0, offset = 0, length = 0, stride = 0, count = 0;
  std::string mode, filter;

  size_t decodedSize() const { return stride * count; }
  auto operator<=>(const Stream&) const = default;
};

// The extension's stream, its sizes checked against the compressed bytes, before anything is decoded.
Stream streamOf(const tinygltf::Model& model, const tinygltf::Value& e, const std::string& where,
                const std::string& file) {
  auto fail = [&](const std::string& why) { failLoad(file, where + ": " + why); };
  const int64_t buffer = integer(e, "buffer", -1), offset = integer(e, "byteOffset", 0);
  const int64_t length = integer(e, "byteLength", -1), stride = integer(e, "byteStride", -1);
  const int64_t count = integer(e, "count", -1);
  if (buffer < 0 || size_t(buffer) >= model.buffers.size()) fail("'buffer' names no buffer");
  const size_t available = model.buffers[size_t(buffer)].data.size();
  if (offset < 0 || length < 0 || size_t(offset) > available || size_t(length) > available - size_t(offset))
    fail("'byteOffset' and 'byteLength' reach beyond the buffer");
  if (stride <= 0 || stride > 256 || count < 0) fail("'byteStride' or 'count' is missing or out of range");
  Stream s{size_t(buffer), size_t(offset),      size_t(length),           size_t(stride),
           size_t(count),  text(e, "mode", ""), text(e, "filter", "NONE")};
  if (s.decodedSize() > s.length * kMaxExpansion + 4096)
    fail("'count' claims more data than the compressed bytes hold");
  if (s.mode == "ATTRIBUTES") {
    if (s.stride % 4 != 0) fail("the byteStride of ATTRIBUTES must be a multiple of 4");
  } else if (s.mode == "TRIANGLES" || s.mode == "INDICES") {
    if (s.stride != 2 && s.stride != 4) fail("the byteStride of " + s.mode + " must be 2 or 4");
    if (s.mode == "TRIANGLES" && s.count % 3 != 0) fail("the count of TRIANGLES must be a multiple of 3");
    if (s.filter != "NONE") fail("filters apply to ATTRIBUTES only");
  } else {
    fail("mode '" + s.mode + "' is not ATTRIBUTES, TRIANGLES or INDICES");
  }
  if (s.filter == "OCTAHEDRAL" && s.stride != 4 && s.stride != 8)
    fail("the byteStride of the OCTAHEDRAL filter must be 4 or 8");
  if (s.filter == "QUATERNION" && s.stride != 8) fail("the byteStride of the QUATERNION filter must be 8");
  if (s.filter != "NONE" && s.filter != "OCTAHEDRAL" && s.filter != "QUATERNION" && s.filter != "EXPONENTIAL")
    fail("filter '" + s.filter + "' is not NONE, OCTAHEDRAL, QUATERNION or EXPONENTIAL");
  return s;
}

std::vector<unsigned char> decode(const tinygltf::Model& model, const Stream& s, const std::string& where,
                                  const std::string& file) {
  std::vector<unsigned char> decoded(s.decodedSize());
  const unsigned char* compressed = model.buffers[s.buffer].data.data() + s.offset;
  const int status =
      s.mode == "ATTRIBUTES" ? meshopt_decodeVertexBuffer(decoded.data(), s.count, s.stride, compressed, s.length)
      : s.mode == "TRIANGLES" ? meshopt_decodeIndexBuffer(decoded.data(), s.count, s.stride, compressed, s.length)
                              : meshopt_decodeIndexSequence(decoded.data(), s.count, s.stride, compressed, s.length);
  if (status != 0) failLoad(file, where + ": the compressed data cannot be decoded");
  if (s.filter == "OCTAHEDRAL")
    meshopt_decodeFilterOct(decoded.data(), s.count, s.stride);
  else if (s.filter == "QUATERNION")
    meshopt_decodeFilterQuat(decoded.data(), s.count, s.stride);
  else if (s.filter == "EXPONENTIAL")
    meshopt_decodeFilterExp(decoded.data(), s.count, s.stride);
  return decoded;
}

}  // namespace

void decodeMeshoptBufferViews(tinygltf::Model& model, const std::string& file, GltfBufferCharge& charge) {
  const std::string name(kExtension);
  // Every stream is read, and the decoded sizes of the distinct ones added up and charged, before any is decoded:
  // bufferViews that name overlapping compressed bytes could otherwise claim any multiple of the file, and streams
  // within that bound may still decode to more than the machine has.
  std::vector<std::pair<size_t, Stream>> views;  // (bufferView, its stream)
  std::map<Stream, std::optional<uint32_t>> decodedBuffers;
  std::set<size_t> sourceBuffers;
  size_t compressedBytes = 0, decodedBytes = 0;
  for (size_t i = 0; i < model.bufferViews.size(); ++i) {
    auto e = model.bufferViews[i].extensions.find(name);
    if (e == model.bufferViews[i].extensions.end()) continue;
    const std::string where = "bufferViews[" + std::to_string(i) + "].extensions." + name;
    const Stream s = streamOf(model, e->second, where, file);
    views.emplace_back(i, s);
    if (sourceBuffers.insert(s.buffer).second) compressedBytes += model.buffers[s.buffer].data.size();
    if (!decodedBuffers.emplace(s, std::nullopt).second) continue;
    decodedBytes += s.decodedSize();
    if (decodedBytes > compressedBytes * kMaxExpansion + kDecodedSlack)
      failLoad(file, where + ": the compressed bufferViews up to this one decode to " + std::to_string(decodedBytes) +
                         " bytes, more than " + std::to_string(kMaxExpansion) + " times the " +
                         std::to_string(compressedBytes) + " bytes of the buffers they read");
    charge.charge(s.decodedSize(), "bufferViews[" + std::to_string(i) + "] decoded from " + name);
  }
  for (const auto& [index, s] : views) {
    std::optional<uint32_t>& buffer = decodedBuffers[s];
    if (!buffer) {
      tinygltf::Buffer out;
      out.data = decode(model, s, "bufferViews[" + std::to_string(index) + "].extensions." + name, file);
      buffer = uint32_t(model.buffers.size());
      model.buffers.push_back(std::move(out));
    }
    tinygltf::BufferView& view = model.bufferViews[index];
    view.buffer = int(*buffer);
    view.byteOffset = 0;
    view.byteLength = s.decodedSize();
    if (s.mode == "ATTRIBUTES") view.byteStride = s.stride;
  }
}

#endif

}  // namespace candela
