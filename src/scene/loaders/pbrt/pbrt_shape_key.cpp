#include "scene/loaders/pbrt/pbrt_shape_key.h"

#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>

namespace candela {

namespace {

// Keys of inline meshes longer than this are not kept: such meshes are rarely repeated, and the key would cost
// as much memory as the mesh.
constexpr size_t kMaxKeyBytes = 4096;

bool onlyParameter(const PbrtParameters& params, const char* name) {
  for (const PbrtParameter& p : params.list)
    if (p.name != name) return false;
  return true;
}

void appendParameters(std::string& key, const PbrtParameters& params) {
  for (const PbrtParameter& p : params.list) {
    key += '|';
    key += p.type;
    key += ' ';
    key += p.name;
    char number[32];
    for (double v : p.numbers) {
      std::snprintf(number, sizeof(number), " %a", v);  // exact: equal keys mean equal numbers
      key += number;
      if (key.size() > kMaxKeyBytes) return;
    }
    for (const std::string& s : p.strings) {
      key += " \"";
      key += s;
      key += '"';
    }
  }
}

}  // namespace

std::optional<PbrtShapeKey> pbrtShapeKey(const std::string& type, const PbrtParameters& params) {
  PbrtShapeKey shape;
  // A whole sphere, or a disk at height 0 without a hole, of radius r is the one of radius 1 scaled by r.
  if ((type == "sphere" || type == "disk") && onlyParameter(params, "radius")) {
    const float radius = params.getFloat("radius", 1.0f);
    if (radius > 0.0f) {
      shape.unitShape = true;
      shape.unitParams.file = params.file;
      shape.unitParams.line = params.line;
      shape.shapeFromMesh = glm::scale(glm::mat4(1.0f), glm::vec3(radius));
    }
  }
  shape.key = type;
  appendParameters(shape.key, shape.unitShape ? shape.unitParams : params);
  if (shape.key.size() > kMaxKeyBytes) return std::nullopt;
  return shape;
}

}  // namespace candela
