#pragma once
#include <glm/mat4x4.hpp>
#include <optional>
#include <string>

#include "scene/loaders/pbrt/pbrt_parameters.h"

namespace candela {

// How a shape can share the mesh of an earlier one: a key that equal shapes have in common (type and
// parameters, written exactly), the parameters to make the shared mesh from, and the transform that takes that
// mesh to this shape. Whole spheres and flat disks are made once at radius 1 and scaled, so that spheres of any
// radius share one tessellation.
struct PbrtShapeKey {
  std::string key;
  bool unitShape = false;     // the mesh is made from unitParams, not the shape's own parameters
  PbrtParameters unitParams;  // the shape's file and line, without parameters
  glm::mat4 shapeFromMesh{1.0f};
};

// The key of a shape whose mesh depends on nothing but its type and parameters (plymesh, the quadrics,
// loopsubdiv, and meshes given inline when their parameters are short); nothing for shapes not worth keying.
// Reads (and so marks used) the parameters it folds into the transform.
std::optional<PbrtShapeKey> pbrtShapeKey(const std::string& type, const PbrtParameters& params);

}  // namespace candela
