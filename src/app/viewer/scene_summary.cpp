#include "app/viewer/scene_summary.h"

#include <algorithm>

namespace candela {

void Bounds3::extend(Vec3 p) {
  lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
  hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
}

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
