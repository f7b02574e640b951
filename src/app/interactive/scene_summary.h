#pragma once
#include <cstddef>

#include "core/bounds.h"
#include "scene/scene.h"

namespace candela {

// What the viewer's panel shows about a scene, and the world-space bounds the camera controls scale with.
struct SceneSummary {
  size_t vertices = 0;   // over instances
  size_t triangles = 0;  // over instances
  size_t meshes = 0;
  size_t instances = 0;
  size_t materials = 0;
  size_t textures = 0;
  Bounds3 bounds;
};

SceneSummary summarizeScene(const Scene& scene);

}  // namespace candela
