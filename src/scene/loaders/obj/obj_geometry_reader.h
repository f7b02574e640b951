#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "core/math.h"
#include "io/load_diagnostics.h"
#include "scene/loaders/obj/obj_text_source.h"

namespace candela {

constexpr uint32_t kObjNoMaterial = ~0u;

// The geometry of an OBJ file in compact arrays: attributes as the file defines them, and triangles whose corners
// refer to them.
struct ObjGeometry {
  std::vector<Vec3> positions, normals;
  std::vector<Vec2> uvs;                          // as written: v runs up the image
  std::vector<uint32_t> cornerPositions;          // 3 per triangle
  std::vector<int32_t> cornerUvs, cornerNormals;  // 3 per triangle; -1: none
  std::vector<uint32_t> smoothingGroups;          // per triangle; 0: none
  std::vector<uint32_t> materials;  // per triangle: what ObjMaterialResolver::find gave, or kObjNoMaterial

  size_t triangleCount() const { return materials.size(); }
};

// What "mtllib" and "usemtl" statements mean; asked in file order.
class ObjMaterialResolver {
 public:
  virtual ~ObjMaterialResolver() = default;
  virtual void loadLibraries(size_t line, std::string_view names) = 0;
  // The material called `name`, or kObjNoMaterial.
  virtual uint32_t find(size_t line, std::string_view name) = 0;
};

struct ObjReadOptions {
  size_t windowBytes = size_t(16) << 20;  // text read at a time
  size_t chunkBytes = size_t(1) << 20;    // text parsed by one task
};

// Reads the geometry of OBJ text: each window of text is cut into chunks of whole lines that are parsed in
// parallel (obj_chunk_parser.h) after a quick count of their attribute statements, which tells each chunk where
// its relative references point. Polygons are triangulated once the whole file is read. Errors throw LoadError
// naming `name` and the line; problems a load survives (skin weights, faces with fewer than three corners,
// references to missing texture coordinates or normals, line and point elements) go to `warnings`.
ObjGeometry readObjGeometry(const std::string& name, ObjTextSource& text, ObjMaterialResolver& materials,
                            LoadWarnings& warnings, const ObjReadOptions& options = {});

}  // namespace candela
