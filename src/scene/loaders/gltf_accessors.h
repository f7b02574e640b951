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
class GltfAccessorReader {
 public:
  GltfAccessorReader(const tinygltf::Model& model, std::string file) : model_(model), file_(std::move(file)) {}

  std::vector<Vec3> readVec3(int accessor, const std::string& where) const;
  std::vector<Vec4> readVec4(int accessor, const std::string& where) const;
  std::vector<Vec2> readTexcoords(int accessor, const std::string& where) const;  // float or normalised integers
  std::vector<uint32_t> readIndices(int accessor, const std::string& where) const;
  size_t count(int accessor, const std::string& where) const;

 private:
  struct View {
    const uint8_t* data;
    size_t count;
    size_t stride;
    int componentType;
    bool normalized;
  };
  View view(int accessor, int expectedType, const std::string& where) const;
  [[noreturn]] void fail(const std::string& where, const std::string& what) const;

  const tinygltf::Model& model_;
  std::string file_;
};

}  // namespace candela
