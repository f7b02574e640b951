#include "scene/loaders/gltf_accessors.h"

#include <cstring>

#include "scene/loaders/load_diagnostics.h"

namespace candela {

namespace {

float readComponent(const uint8_t* p, int componentType, bool normalized) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: {
      float f;
      std::memcpy(&f, p, 4);
      return f;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return normalized ? float(*p) / 255.0f : float(*p);
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
    default:
      return 0.0f;
  }
}

const char* typeName(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return "SCALAR";
    case TINYGLTF_TYPE_VEC2: return "VEC2";
    case TINYGLTF_TYPE_VEC3: return "VEC3";
    case TINYGLTF_TYPE_VEC4: return "VEC4";
    default: return "another type";
  }
}

}  // namespace

void GltfAccessorReader::fail(const std::string& where, const std::string& what) const {
  failLoad(file_, where + ": " + what);
}

size_t GltfAccessorReader::count(int accessor, const std::string& where) const {
  if (accessor < 0 || size_t(accessor) >= model_.accessors.size())
    fail(where, "accessor " + std::to_string(accessor) + " does not exist");
  return model_.accessors[size_t(accessor)].count;
}

GltfAccessorReader::View GltfAccessorReader::view(int index, int expectedType, const std::string& where) const {
  count(index, where);
  const tinygltf::Accessor& a = model_.accessors[size_t(index)];
  std::string at = where + " (accessors[" + std::to_string(index) + "])";
  if (a.type != expectedType) fail(at, std::string("expected ") + typeName(expectedType) + ", found " + typeName(a.type));
  if (a.sparse.isSparse) fail(at, "sparse accessors are not supported");
  int componentSize = tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType));
  int components = tinygltf::GetNumComponentsInType(uint32_t(a.type));
  if (componentSize <= 0 || components <= 0) fail(at, "unknown component type");
  if (a.bufferView < 0 || size_t(a.bufferView) >= model_.bufferViews.size())
    fail(at, "bufferView " + std::to_string(a.bufferView) + " does not exist");
  const tinygltf::BufferView& bv = model_.bufferViews[size_t(a.bufferView)];
  if (bv.buffer < 0 || size_t(bv.buffer) >= model_.buffers.size())
    fail(at, "buffer " + std::to_string(bv.buffer) + " does not exist");
  const tinygltf::Buffer& buffer = model_.buffers[size_t(bv.buffer)];
  size_t elementSize = size_t(componentSize) * size_t(components);
  size_t stride = bv.byteStride ? bv.byteStride : elementSize;
  if (stride < elementSize || stride % size_t(componentSize) != 0) fail(at, "byteStride " + std::to_string(stride) + " is invalid");
  if (bv.byteOffset > buffer.data.size() || bv.byteLength > buffer.data.size() - bv.byteOffset)
    fail(at, "bufferView " + std::to_string(a.bufferView) + " reaches past the end of buffer " +
                 std::to_string(bv.buffer) + " (" + std::to_string(buffer.data.size()) + " bytes)");
  if (a.count > 0) {
    // The last element ends at byteOffset + (count - 1) * stride + elementSize; computed without overflow.
    size_t available = bv.byteLength;
    if (a.byteOffset > available || elementSize > available - a.byteOffset ||
        (a.count - 1) > (available - a.byteOffset - elementSize) / stride)
      fail(at, std::to_string(a.count) + " elements do not fit in bufferView " + std::to_string(a.bufferView));
  }
  return {buffer.data.data() + bv.byteOffset + a.byteOffset, a.count, stride, a.componentType, a.normalized};
}

std::vector<Vec3> GltfAccessorReader::readVec3(int accessor, const std::string& where) const {
  View v = view(accessor, TINYGLTF_TYPE_VEC3, where);
  if (v.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT) fail(where, "expected float components");
  std::vector<Vec3> out(v.count);
  for (size_t i = 0; i < v.count; ++i) {
    std::memcpy(&out[i], v.data + i * v.stride, sizeof(Vec3));
    if (!isFinite(out[i])) fail(where, "element " + std::to_string(i) + " is not finite");
  }
  return out;
}

std::vector<Vec4> GltfAccessorReader::readVec4(int accessor, const std::string& where) const {
  View v = view(accessor, TINYGLTF_TYPE_VEC4, where);
  if (v.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT) fail(where, "expected float components");
  std::vector<Vec4> out(v.count);
  for (size_t i = 0; i < v.count; ++i) std::memcpy(&out[i], v.data + i * v.stride, sizeof(Vec4));
  return out;
}

std::vector<Vec2> GltfAccessorReader::readTexcoords(int accessor, const std::string& where) const {
  View v = view(accessor, TINYGLTF_TYPE_VEC2, where);
  bool ok = v.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT ||
            (v.normalized && (v.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                              v.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT));
  if (!ok) fail(where, "expected float or normalised unsigned components");
  int size = tinygltf::GetComponentSizeInBytes(uint32_t(v.componentType));
  std::vector<Vec2> out(v.count);
  for (size_t i = 0; i < v.count; ++i) {
    const uint8_t* p = v.data + i * v.stride;
    out[i] = {readComponent(p, v.componentType, v.normalized), readComponent(p + size, v.componentType, v.normalized)};
    if (!std::isfinite(out[i].x) || !std::isfinite(out[i].y)) fail(where, "element " + std::to_string(i) + " is not finite");
  }
  return out;
}

std::vector<uint32_t> GltfAccessorReader::readIndices(int accessor, const std::string& where) const {
  View v = view(accessor, TINYGLTF_TYPE_SCALAR, where);
  std::vector<uint32_t> out(v.count);
  switch (v.componentType) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      for (size_t i = 0; i < v.count; ++i) out[i] = v.data[i * v.stride];
      break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      for (size_t i = 0; i < v.count; ++i) {
        uint16_t x;
        std::memcpy(&x, v.data + i * v.stride, 2);
        out[i] = x;
      }
      break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      for (size_t i = 0; i < v.count; ++i) std::memcpy(&out[i], v.data + i * v.stride, 4);
      break;
    default:
      fail(where, "indices must be unsigned byte, short or int");
  }
  return out;
}

}  // namespace candela
