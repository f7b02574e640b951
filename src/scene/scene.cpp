#include "scene/scene.h"

#include <stdexcept>

namespace candela {

size_t Scene::triangleCount() const {
  size_t n = 0;
  for (const Instance& inst : instances) n += meshes[inst.meshId].triangleCount();
  return n;
}

namespace {
bool finite(Vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
}  // namespace

void validateScene(const Scene& scene) {
  auto fail = [&](const std::string& what) { throw std::runtime_error("scene '" + scene.name + "': " + what); };
  for (const Mesh& mesh : scene.meshes) {
    if (mesh.indices.size() % 3 != 0) fail("mesh '" + mesh.name + "' has an index count not divisible by 3");
    if (mesh.triangleMaterials.size() != mesh.triangleCount())
      fail("mesh '" + mesh.name + "' needs one material id per triangle");
    if (!mesh.normals.empty() && mesh.normals.size() != mesh.positions.size())
      fail("mesh '" + mesh.name + "' has " + std::to_string(mesh.normals.size()) + " normals for " +
           std::to_string(mesh.positions.size()) + " positions");
    for (uint32_t index : mesh.indices)
      if (index >= mesh.positions.size()) fail("mesh '" + mesh.name + "' indexes past its vertices");
    for (uint32_t id : mesh.triangleMaterials)
      if (id >= scene.materials.size()) fail("mesh '" + mesh.name + "' uses a missing material");
    for (Vec3 p : mesh.positions)
      if (!finite(p)) fail("mesh '" + mesh.name + "' has a non-finite vertex position");
  }
  for (const Instance& inst : scene.instances)
    if (inst.meshId >= scene.meshes.size()) fail("an instance refers to a missing mesh");
  for (const Material& m : scene.materials)
    if (!finite(m.baseColor) || !finite(m.emission)) fail("a material has non-finite parameters");
}

}  // namespace candela
