#pragma once
#include <cstddef>

#include "scene/scene.h"

namespace candela {

struct Bounds3 {
  Vec3 lo{kInf, kInf, kInf};
  Vec3 hi{-kInf, -kInf, -kInf};

  bool empty() const { return lo.x > hi.x; }
  void extend(Vec3 p);
  Vec3 centre() const { return (lo + hi) * 0.5f; }
  float radius() const { return empty() ? 0.0f : 0.5f * length(hi - lo); }
};

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
