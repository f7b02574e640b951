#pragma once
#include <tiny_gltf.h>

#include <cstdint>
#include <string>
#include <vector>

#include "core/math.h"

namespace candela {

// Reads glTF accessors into plain arrays, checking every index, offset, stride and length against the buffers
// that are really there; a problem throws LoadError naming the file and the JSON path of the accessor user
// (`where`, e.g. "meshes[2].primitives[0].attributes.POSITION").
//
// Attributes may be floats or, as KHR_mesh_quantization allows, 8- or 16-bit integers: normalised ones map to
// [0, 1] or [-1, 1] as the specification says, the others keep their integer values (a node transform then
// scales them). Sparse accessors (core glTF 2.0) are supported: the listed elements replace those of the base
// bufferView, or of zeros when there is none. Values are returned as they are, non-finite ones included:
// repairing or dropping bad elements is left to the scene's repair after loading. What the distinct accessors read
// decode to is bounded by 16 times the bytes of the file's buffers (decoded Draco and meshopt data included), or
// 512 MiB where that is more.
class GltfAccessorReader {
 public:
  GltfAccessorReader(const tinygltf::Model& model, std::string file);

  std::vector<Vec3> readVec3(int accessor, const std::string& where) const;
  std::vector<Vec4> readVec4(int accessor, const std::string& where) const;
  std::vector<Vec2> readVec2(int accessor, const std::string& where) const;
  std::vector<float> readScalars(int accessor, const std::string& where) const;
  // MAT4 elements, 16 column-major floats each; only float components (glTF pads the columns of smaller ones).
  std::vector<float> readMatrices(int accessor, const std::string& where) const;
  // VEC3 or VEC4 colours; a VEC3 accessor gets alpha 1.
  std::vector<Vec4> readColours(int accessor, const std::string& where) const;
  std::vector<uint32_t> readIndices(int accessor, const std::string& where) const;
  size_t count(int accessor, const std::string& where) const;

 private:
  // Elements laid out in memory: `count` of them, `stride` bytes apart.
  struct View {
    const uint8_t* data = nullptr;
    size_t count = 0;
    size_t stride = 0;
  };
  View bytes(int bufferView, size_t byteOffset, size_t count, size_t elementSize, const std::string& at) const;
  // All `components` values of every element, as floats, with sparse elements substituted.
  std::vector<float> readFloats(int accessor, int type, const std::string& where) const;
  const tinygltf::Accessor& accessor(int index, const std::string& where) const;
  [[noreturn]] void fail(const std::string& where, const std::string& what) const;
  // Adds the decoded size of accessors[index], the first time it is read, to what the file's distinct accessors
  // decode to, and refuses the file when that passes the budget: accessors that alias the same bytes at
  // different offsets (or sparse ones over zeros) could otherwise make a small file ask for any amount of memory.
  void charge(int index, uint64_t bytes, const std::string& at) const;

  const tinygltf::Model& model_;
  std::string file_;
  uint64_t budget_ = 0;  // bytes
  mutable uint64_t decoded_ = 0;
  mutable std::vector<bool> charged_;  // by accessor
};

}  // namespace candela
