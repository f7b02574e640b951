#include "scene/loaders/gltf/gltf_draco.h"

#ifdef CANDELA_HAS_DRACO
#include <draco/compression/decode.h>
#include <draco/mesh/mesh.h>
#endif
#include <nlohmann/json.hpp>

#include <cstring>
#include <map>
#include <optional>
#include <string_view>
#include <tuple>

#include "io/load_diagnostics.h"
#include "scene/loaders/gltf/gltf_glb.h"

namespace candela {

bool gltfDracoAvailable() {
#ifdef CANDELA_HAS_DRACO
  return true;
#else
  return false;
#endif
}

namespace {

constexpr std::string_view kExtension = "KHR_draco_mesh_compression";

}  // namespace

std::optional<std::vector<uint8_t>> withoutDracoIndices(const uint8_t* data, size_t size) {
  if (!gltfDracoAvailable()) return std::nullopt;
  std::optional<GltfJson> json = gltfJsonMentioning(data, size, kExtension);
  if (!json || !json->doc.contains("meshes") || !json->doc["meshes"].is_array()) return std::nullopt;
  nlohmann::json& doc = json->doc;
  bool changed = false;
  for (nlohmann::json& mesh : doc["meshes"]) {
    if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array()) continue;
    for (nlohmann::json& primitive : mesh["primitives"]) {
      if (!primitive.is_object() || !primitive.contains("indices")) continue;
      auto extensions = primitive.find("extensions");
      if (extensions == primitive.end() || !extensions->is_object() || !extensions->contains(kExtension)) continue;
      primitive.erase("indices");
      changed = true;
    }
  }
  if (!changed) return std::nullopt;
  return withRewrittenJson(data, size, *json);
}

#ifndef CANDELA_HAS_DRACO

void decodeDracoPrimitives(tinygltf::Model&, const std::string&, GltfBufferCharge&) {}

#else

namespace {

// Writes attribute `a` of every point as `components` values of type T, from `out` on.
template <class T>
bool convertPoints(const draco::PointAttribute& a, size_t points, int components, uint8_t* out) {
  T values[4];
  for (uint32_t p = 0; p < points; ++p) {
    if (!a.ConvertValue<T>(a.mapped_index(draco::PointIndex(p)), int8_t(components), values)) return false;
    std::memcpy(out, values, sizeof(T) * size_t(components));
    out += sizeof(T) * size_t(components);
  }
  return true;
}

bool convertPoints(const draco::PointAttribute& a, size_t points, int components, int componentType, uint8_t* out) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return convertPoints<int8_t>(a, points, components, out);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return convertPoints<uint8_t>(a, points, components, out);
    case TINYGLTF_COMPONENT_TYPE_SHORT: return convertPoints<int16_t>(a, points, components, out);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return convertPoints<uint16_t>(a, points, components, out);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return convertPoints<uint32_t>(a, points, components, out);
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return convertPoints<float>(a, points, components, out);
    default: return false;
  }
}

class DracoPrimitiveDecoder {
 public:
  // `primitive` is the primitive's JSON path ("meshes[2].primitives[0]").
  DracoPrimitiveDecoder(tinygltf::Model& model, const std::string& file, const std::string& primitive,
                        GltfBufferCharge& charge)
      : model_(model),
        file_(file),
        primitive_(primitive),
        where_(primitive + ".extensions." + std::string(kExtension)),
        charge_(charge) {}

  void decode(tinygltf::Primitive& primitive, const tinygltf::Value& extension) {
    if (!extension.IsObject()) fail("", "expected an object");
    const std::unique_ptr<draco::Mesh> mesh = decodeMesh(extension);
    const size_t points = mesh->num_points();
    const tinygltf::Value& attributes = extension.Get("attributes");
    if (!attributes.IsObject()) fail(".attributes", "expected an object of Draco attribute ids");
    charge_.charge(decodedBytes(primitive, attributes, *mesh), primitive_ + " decoded from " + std::string(kExtension));
    tinygltf::Buffer decoded;
    for (const std::string& name : attributes.Keys()) {
      const std::string at = ".attributes." + name;
      auto used = primitive.attributes.find(name);
      if (used == primitive.attributes.end()) fail(at, "the primitive has no such attribute");
      const tinygltf::Value& id = attributes.Get(name);
      const draco::PointAttribute* source = id.IsInt() && id.GetNumberAsInt() >= 0
                                                ? mesh->GetAttributeByUniqueId(uint32_t(id.GetNumberAsInt()))
                                                : nullptr;
      if (!source) fail(at, "the Draco data have no attribute with this id");
      used->second = addAccessor(decoded, accessorOf(used->second, at), *source, points, at);
    }
    primitive.indices = addIndices(decoded, *mesh, points);
    primitive.mode = TINYGLTF_MODE_TRIANGLES;  // Draco's faces are a triangle list
    model_.buffers.push_back(std::move(decoded));
  }

 private:
  [[noreturn]] void fail(const std::string& at, const std::string& what) const {
    failLoad(file_, where_ + at + ": " + what);
  }

  // The bytes decode() appends for the mesh: each named attribute at its accessor's layout (3 bytes of alignment
  // at most before each) and the indices. Attributes the checks below refuse count as nothing.
  uint64_t decodedBytes(const tinygltf::Primitive& primitive, const tinygltf::Value& attributes,
                        const draco::Mesh& mesh) const {
    uint64_t bytes = uint64_t(mesh.num_faces()) * 3 * 4;
    for (const std::string& name : attributes.Keys()) {
      auto used = primitive.attributes.find(name);
      if (used == primitive.attributes.end() || used->second < 0 || size_t(used->second) >= model_.accessors.size())
        continue;
      const tinygltf::Accessor& a = model_.accessors[size_t(used->second)];
      const int components = tinygltf::GetNumComponentsInType(uint32_t(a.type));
      const int componentSize = tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType));
      if (components > 0 && componentSize > 0)
        bytes += uint64_t(mesh.num_points()) * uint64_t(components) * uint64_t(componentSize) + 3;
    }
    return bytes;
  }

  std::unique_ptr<draco::Mesh> decodeMesh(const tinygltf::Value& extension) const {
    const tinygltf::Value& index = extension.Get("bufferView");
    if (!index.IsInt()) fail(".bufferView", "expected a bufferView index");
    const int view = index.GetNumberAsInt();
    if (view < 0 || size_t(view) >= model_.bufferViews.size())
      fail(".bufferView", "bufferView " + std::to_string(view) + " does not exist");
    const tinygltf::BufferView& bv = model_.bufferViews[size_t(view)];
    if (bv.buffer < 0 || size_t(bv.buffer) >= model_.buffers.size())
      fail(".bufferView", "buffer " + std::to_string(bv.buffer) + " does not exist");
    const std::vector<unsigned char>& bytes = model_.buffers[size_t(bv.buffer)].data;
    if (bv.byteOffset > bytes.size() || bv.byteLength > bytes.size() - bv.byteOffset)
      fail(".bufferView", "bufferView " + std::to_string(view) + " reaches past the end of its buffer");
    draco::DecoderBuffer in;
    in.Init(reinterpret_cast<const char*>(bytes.data() + bv.byteOffset), bv.byteLength);
    draco::Decoder decoder;
    auto result = decoder.DecodeMeshFromBuffer(&in);
    if (!result.ok()) fail("", "the Draco data cannot be decoded (" + result.status().error_msg_string() + ")");
    return std::move(result).value();
  }

  tinygltf::Accessor accessorOf(int index, const std::string& at) const {
    if (index < 0 || size_t(index) >= model_.accessors.size())
      fail(at, "accessor " + std::to_string(index) + " does not exist");
    return model_.accessors[size_t(index)];
  }

  // Appends the values of every point to `decoded` and returns the accessor that reads them.
  int addAccessor(tinygltf::Buffer& decoded, tinygltf::Accessor accessor, const draco::PointAttribute& source,
                  size_t points, const std::string& at) {
    const int components = tinygltf::GetNumComponentsInType(uint32_t(accessor.type));
    const int componentSize = tinygltf::GetComponentSizeInBytes(uint32_t(accessor.componentType));
    if (components < 1 || components > 4 || componentSize < 1)
      fail(at, "the accessor's type or component type is not one an attribute can have");
    if (source.num_components() != components)
      fail(at, "the Draco attribute has " + std::to_string(source.num_components()) + " components, the accessor " +
                   std::to_string(components));
    if (!source.is_mapping_identity() && source.indices_map_size() < points)
      fail(at, "the Draco attribute maps fewer points than the mesh has");
    const size_t at0 = (decoded.data.size() + 3) / 4 * 4;  // attribute data stay 4-byte aligned
    const size_t length = points * size_t(components) * size_t(componentSize);
    decoded.data.resize(at0 + length);
    if (!convertPoints(source, points, components, accessor.componentType, decoded.data.data() + at0))
      fail(at, "the Draco attribute's values cannot be read as the accessor's components");
    accessor.bufferView = addView(at0, length);
    accessor.byteOffset = 0;
    accessor.count = points;
    accessor.sparse.isSparse = false;
    accessor.sparse.count = 0;
    model_.accessors.push_back(accessor);
    return int(model_.accessors.size() - 1);
  }

  int addIndices(tinygltf::Buffer& decoded, const draco::Mesh& mesh, size_t points) {
    const size_t at0 = (decoded.data.size() + 3) / 4 * 4;
    const size_t count = size_t(mesh.num_faces()) * 3;
    decoded.data.resize(at0 + count * 4);
    uint8_t* out = decoded.data.data() + at0;
    for (draco::FaceIndex f(0); f < mesh.num_faces(); ++f)
      for (int k = 0; k < 3; ++k) {
        const uint32_t index = mesh.face(f)[k].value();
        if (index >= points)
          fail("", "a Draco face names point " + std::to_string(index) + " of " + std::to_string(points));
        std::memcpy(out, &index, 4);
        out += 4;
      }
    tinygltf::Accessor accessor;
    accessor.bufferView = addView(at0, count * 4);
    accessor.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    accessor.type = TINYGLTF_TYPE_SCALAR;
    accessor.count = count;
    model_.accessors.push_back(accessor);
    return int(model_.accessors.size() - 1);
  }

  // A bufferView of the buffer that decode() appends.
  int addView(size_t offset, size_t length) {
    tinygltf::BufferView view;
    view.buffer = int(model_.buffers.size());
    view.byteOffset = offset;
    view.byteLength = length;
    model_.bufferViews.push_back(view);
    return int(model_.bufferViews.size() - 1);
  }

  tinygltf::Model& model_;
  const std::string& file_;
  std::string primitive_, where_;
  GltfBufferCharge& charge_;
};

// What identifies the result of decoding a Draco primitive: the compressed bytes, and each attribute's name,
// Draco id and accessor layout.
struct DracoStream {
  int buffer;
  size_t offset, length;
  std::vector<std::tuple<std::string, int, int, int, bool>> attributes;  // name, id, componentType, type, normalized
  auto operator<=>(const DracoStream&) const = default;
};

// The accessors a decoded primitive names.
struct DecodedPrimitive {
  std::map<std::string, int> attributes;
  int indices = -1;
};

// The primitive's stream, or nothing where the extension is malformed (the decoder then says how).
std::optional<DracoStream> streamOf(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                                    const tinygltf::Value& extension) {
  if (!extension.IsObject() || !extension.Get("bufferView").IsInt() || !extension.Get("attributes").IsObject())
    return std::nullopt;
  const int view = extension.Get("bufferView").GetNumberAsInt();
  if (view < 0 || size_t(view) >= model.bufferViews.size()) return std::nullopt;
  const tinygltf::BufferView& bv = model.bufferViews[size_t(view)];
  DracoStream s{bv.buffer, bv.byteOffset, bv.byteLength, {}};
  const tinygltf::Value& attributes = extension.Get("attributes");
  for (const std::string& name : attributes.Keys()) {
    auto used = primitive.attributes.find(name);
    const tinygltf::Value& id = attributes.Get(name);
    if (used == primitive.attributes.end() || !id.IsInt() || used->second < 0 ||
        size_t(used->second) >= model.accessors.size())
      return std::nullopt;
    const tinygltf::Accessor& a = model.accessors[size_t(used->second)];
    s.attributes.emplace_back(name, id.GetNumberAsInt(), a.componentType, a.type, a.normalized);
  }
  return s;
}

}  // namespace

void decodeDracoPrimitives(tinygltf::Model& model, const std::string& file, GltfBufferCharge& charge) {
  // Primitives that decode the same bytes into the same accessors share what the first of them decoded.
  std::map<DracoStream, DecodedPrimitive> decoded;
  for (size_t m = 0; m < model.meshes.size(); ++m)
    for (size_t p = 0; p < model.meshes[m].primitives.size(); ++p) {
      tinygltf::Primitive& primitive = model.meshes[m].primitives[p];
      auto extension = primitive.extensions.find(std::string(kExtension));
      if (extension == primitive.extensions.end()) continue;
      // Points and lines are left out by the loader; Draco stores them as point clouds, which are not decoded.
      if (primitive.mode >= 0 && primitive.mode < TINYGLTF_MODE_TRIANGLES) continue;
      const std::string path = "meshes[" + std::to_string(m) + "].primitives[" + std::to_string(p) + "]";
      const std::optional<DracoStream> stream = streamOf(model, primitive, extension->second);
      if (auto it = stream ? decoded.find(*stream) : decoded.end(); it != decoded.end()) {
        for (const auto& [name, accessor] : it->second.attributes) primitive.attributes[name] = accessor;
        primitive.indices = it->second.indices;
        primitive.mode = TINYGLTF_MODE_TRIANGLES;
        continue;
      }
      DracoPrimitiveDecoder(model, file, path, charge).decode(primitive, extension->second);
      if (!stream) continue;
      DecodedPrimitive& shared = decoded[*stream];
      for (const auto& name : extension->second.Get("attributes").Keys())
        shared.attributes[name] = primitive.attributes[name];
      shared.indices = primitive.indices;
    }
}

#endif

}  // namespace candela
