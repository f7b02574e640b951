#include "app/interactive/scene_summary.h"

#include <algorithm>

namespace candela {

SceneSummary summarizeScene(const Scene& scene) {
  SceneSummary summary;
  summary.meshes = scene.meshes.size();
  summary.instances = scene.instances.size();
  summary.materials = scene.materials.size();
  summary.textures = scene.textures.size();
  for (const Instance& instance : scene.instances) {
    const Mesh& mesh = scene.meshes[instance.meshId];
    summary.vertices += mesh.positions.size();
    summary.triangles += mesh.triangleCount();
    for (Vec3 p : mesh.positions) summary.bounds.extend(instance.objectToWorld.point(p));
  }
  return summary;
}

}  // namespace candela
