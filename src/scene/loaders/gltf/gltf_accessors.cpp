#include "scene/loaders/gltf/gltf_accessors.h"

#include <algorithm>
#include <cstring>

#include "io/load_diagnostics.h"

namespace candela {

namespace {

constexpr size_t kMaxZeroBasedElements = size_t(1) << 26;
// The budget of what the file's distinct accessors decode to (GltfAccessorReader::charge). Decoding widens 8- and
// 16-bit components to floats (at most 4 times) and a file's buffers hold images too; the floor leaves room for
// sparse morph targets over zeros.
constexpr uint64_t kDecodedPerBufferByte = 16;
constexpr uint64_t kMinDecodedBudget = uint64_t(512) << 20;

// One component as glTF defines its value: normalised integers map to [0, 1] (unsigned) or [-1, 1] (signed).
float readComponent(const uint8_t* p, int componentType, bool normalized) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: {
      float f;
      std::memcpy(&f, p, 4);
      return f;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? float(*p) / 255.0f : float(*p);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      uint16_t v;
      std::memcpy(&v, p, 2);
      return normalized ? float(v) / 65535.0f : float(v);
    }
    case TINYGLTF_COMPONENT_TYPE_BYTE:
      return normalized ? std::max(float(int8_t(*p)) / 127.0f, -1.0f) : float(int8_t(*p));
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      int16_t v;
      std::memcpy(&v, p, 2);
      return normalized ? std::max(float(v) / 32767.0f, -1.0f) : float(v);
    }
    default: return 0.0f;
  }
}

uint32_t readIndex(const uint8_t* p, int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return *p;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      uint16_t x;
      std::memcpy(&x, p, 2);
      return x;
    }
    default: {
      uint32_t x;
      std::memcpy(&x, p, 4);
      return x;
    }
  }
}

bool isIndexType(int componentType) {
  return componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
         componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
         componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
}

// Attribute components: floats, or the 8- and 16-bit integers KHR_mesh_quantization allows.
bool isAttributeType(int componentType) {
  return componentType == TINYGLTF_COMPONENT_TYPE_FLOAT || componentType == TINYGLTF_COMPONENT_TYPE_BYTE ||
         componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE || componentType == TINYGLTF_COMPONENT_TYPE_SHORT ||
         componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
}

const char* typeName(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return "SCALAR";
    case TINYGLTF_TYPE_VEC2: return "VEC2";
    case TINYGLTF_TYPE_VEC3: return "VEC3";
    case TINYGLTF_TYPE_VEC4: return "VEC4";
    case TINYGLTF_TYPE_MAT4: return "MAT4";
    default: return "another type";
  }
}

}  // namespace

GltfAccessorReader::GltfAccessorReader(const tinygltf::Model& model, std::string file)
    : model_(model), file_(std::move(file)), charged_(model.accessors.size(), false) {
  uint64_t bufferBytes = 0;
  for (const tinygltf::Buffer& b : model.buffers) bufferBytes += b.data.size();
  budget_ = std::max(kMinDecodedBudget, kDecodedPerBufferByte * bufferBytes);
}

void GltfAccessorReader::charge(int index, uint64_t bytes, const std::string& at) const {
  if (charged_[size_t(index)]) return;
  charged_[size_t(index)] = true;
  decoded_ += bytes;
  if (decoded_ > budget_)
    fail(at, "the accessors read up to this one decode to " + std::to_string(decoded_) + " bytes, more than the " +
                 std::to_string(budget_) + " allowed (" + std::to_string(kDecodedPerBufferByte) +
                 " times the bytes of the file's buffers, at least 512 MiB)");
}

void GltfAccessorReader::fail(const std::string& where, const std::string& what) const {
  failLoad(file_, where + ": " + what);
}

const tinygltf::Accessor& GltfAccessorReader::accessor(int index, const std::string& where) const {
  if (index < 0 || size_t(index) >= model_.accessors.size())
    fail(where, "accessor " + std::to_string(index) + " does not exist");
  return model_.accessors[size_t(index)];
}

size_t GltfAccessorReader::count(int index, const std::string& where) const { return accessor(index, where).count; }

GltfAccessorReader::View GltfAccessorReader::bytes(int bufferView, size_t byteOffset, size_t count, size_t elementSize,
                                                   const std::string& at) const {
  if (bufferView < 0 || size_t(bufferView) >= model_.bufferViews.size())
    fail(at, "bufferView " + std::to_string(bufferView) + " does not exist");
  const tinygltf::BufferView& bv = model_.bufferViews[size_t(bufferView)];
  if (bv.buffer < 0 || size_t(bv.buffer) >= model_.buffers.size())
    fail(at, "buffer " + std::to_string(bv.buffer) + " does not exist");
  const tinygltf::Buffer& buffer = model_.buffers[size_t(bv.buffer)];
  size_t stride = bv.byteStride ? bv.byteStride : elementSize;
  if (stride < elementSize) fail(at, "byteStride " + std::to_string(stride) + " is invalid");
  if (bv.byteOffset > buffer.data.size() || bv.byteLength > buffer.data.size() - bv.byteOffset)
    fail(at, "bufferView " + std::to_string(bufferView) + " reaches past the end of buffer " +
                 std::to_string(bv.buffer) + " (" + std::to_string(buffer.data.size()) + " bytes)");
  if (count > 0) {
    // The last element ends at byteOffset + (count - 1) * stride + elementSize; computed without overflow.
    size_t available = bv.byteLength;
    if (byteOffset > available || elementSize > available - byteOffset ||
        (count - 1) > (available - byteOffset - elementSize) / stride)
      fail(at, std::to_string(count) + " elements do not fit in bufferView " + std::to_string(bufferView));
  }
  return {buffer.data.data() + bv.byteOffset + byteOffset, count, stride};
}

std::vector<float> GltfAccessorReader::readFloats(int index, int type, const std::string& where) const {
  const tinygltf::Accessor& a = accessor(index, where);
  std::string at = where + " (accessors[" + std::to_string(index) + "])";
  if (a.type != type) fail(at, std::string("expected ") + typeName(type) + ", found " + typeName(a.type));
  if (!isAttributeType(a.componentType)) fail(at, "expected float, byte or short components");
  const size_t components = size_t(tinygltf::GetNumComponentsInType(uint32_t(a.type)));
  const size_t componentSize = size_t(tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType)));
  const size_t elementSize = components * componentSize;
  auto decode = [&](const uint8_t* p, float* out) {
    for (size_t k = 0; k < components; ++k)
      out[k] = readComponent(p + k * componentSize, a.componentType, a.normalized);
  };

  View base;
  if (a.bufferView >= 0) {
    base = bytes(a.bufferView, a.byteOffset, a.count, elementSize, at);  // checked before anything is allocated
    if (base.stride % componentSize != 0) fail(at, "byteStride " + std::to_string(base.stride) + " is invalid");
  } else if (!a.sparse.isSparse) {
    fail(at, "has neither a bufferView nor sparse values");
  } else if (a.count > kMaxZeroBasedElements) {
    // Nothing in the file backs the zeros the elements start from, so their number needs a bound of its own.
    fail(at, std::to_string(a.count) + " elements without a bufferView are more than candela reads (" +
                 std::to_string(kMaxZeroBasedElements) + ")");
  }
  charge(index, uint64_t(a.count) * components * sizeof(float), at);
  std::vector<float> out(a.count * components, 0.0f);
  for (size_t i = 0; i < base.count; ++i) decode(base.data + i * base.stride, &out[i * components]);
  if (a.sparse.isSparse) {
    const auto& s = a.sparse;
    std::string sparseAt = at + ".sparse";
    if (s.count < 0 || size_t(s.count) > a.count)
      fail(sparseAt, "count " + std::to_string(s.count) + " is not within the accessor's " + std::to_string(a.count));
    if (!isIndexType(s.indices.componentType)) fail(sparseAt + ".indices", "componentType must be unsigned");
    if (s.indices.byteOffset < 0 || s.values.byteOffset < 0) fail(sparseAt, "byteOffset is negative");
    size_t indexSize = size_t(tinygltf::GetComponentSizeInBytes(uint32_t(s.indices.componentType)));
    View indices =
        bytes(s.indices.bufferView, size_t(s.indices.byteOffset), size_t(s.count), indexSize, sparseAt + ".indices");
    View values =
        bytes(s.values.bufferView, size_t(s.values.byteOffset), size_t(s.count), elementSize, sparseAt + ".values");
    // Sparse data are tightly packed whatever the bufferView's byteStride says.
    for (size_t i = 0; i < size_t(s.count); ++i) {
      uint32_t target = readIndex(indices.data + i * indexSize, s.indices.componentType);
      if (target >= a.count)
        fail(sparseAt + ".indices",
             "index " + std::to_string(target) + " is beyond the " + std::to_string(a.count) + " elements");
      decode(values.data + i * elementSize, &out[target * components]);
    }
  }
  return out;
}

std::vector<Vec3> GltfAccessorReader::readVec3(int accessor, const std::string& where) const {
  std::vector<float> f = readFloats(accessor, TINYGLTF_TYPE_VEC3, where);
  std::vector<Vec3> out(f.size() / 3);
  for (size_t i = 0; i < out.size(); ++i) out[i] = {f[3 * i], f[3 * i + 1], f[3 * i + 2]};
  return out;
}

std::vector<float> GltfAccessorReader::readMatrices(int index, const std::string& where) const {
  if (accessor(index, where).componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
    fail(where + " (accessors[" + std::to_string(index) + "])", "expected float matrices");
  return readFloats(index, TINYGLTF_TYPE_MAT4, where);
}

std::vector<Vec4> GltfAccessorReader::readVec4(int accessor, const std::string& where) const {
  std::vector<float> f = readFloats(accessor, TINYGLTF_TYPE_VEC4, where);
  std::vector<Vec4> out(f.size() / 4);
  for (size_t i = 0; i < out.size(); ++i) out[i] = {f[4 * i], f[4 * i + 1], f[4 * i + 2], f[4 * i + 3]};
  return out;
}

std::vector<Vec2> GltfAccessorReader::readVec2(int accessor, const std::string& where) const {
  std::vector<float> f = readFloats(accessor, TINYGLTF_TYPE_VEC2, where);
  std::vector<Vec2> out(f.size() / 2);
  for (size_t i = 0; i < out.size(); ++i) out[i] = {f[2 * i], f[2 * i + 1]};
  return out;
}

std::vector<float> GltfAccessorReader::readScalars(int accessor, const std::string& where) const {
  return readFloats(accessor, TINYGLTF_TYPE_SCALAR, where);
}

std::vector<Vec4> GltfAccessorReader::readColours(int index, const std::string& where) const {
  if (accessor(index, where).type == TINYGLTF_TYPE_VEC4) return readVec4(index, where);
  std::vector<Vec3> rgb = readVec3(index, where);
  std::vector<Vec4> out(rgb.size());
  for (size_t i = 0; i < rgb.size(); ++i) out[i] = {rgb[i].x, rgb[i].y, rgb[i].z, 1.0f};
  return out;
}

std::vector<uint32_t> GltfAccessorReader::readIndices(int index, const std::string& where) const {
  const tinygltf::Accessor& a = accessor(index, where);
  std::string at = where + " (accessors[" + std::to_string(index) + "])";
  if (a.type != TINYGLTF_TYPE_SCALAR) fail(at, std::string("expected SCALAR, found ") + typeName(a.type));
  if (!isIndexType(a.componentType)) fail(where, "indices must be unsigned byte, short or int");
  if (a.sparse.isSparse) fail(at, "sparse index accessors are not supported");
  size_t size = size_t(tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType)));
  View v = bytes(a.bufferView, a.byteOffset, a.count, size, at);
  if (v.stride % size != 0) fail(at, "byteStride " + std::to_string(v.stride) + " is invalid");
  charge(index, uint64_t(v.count) * sizeof(uint32_t), at);
  std::vector<uint32_t> out(v.count);
  for (size_t i = 0; i < v.count; ++i) out[i] = readIndex(v.data + i * v.stride, a.componentType);
  return out;
}

}  // namespace candela
