#include "scene/scene.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "scene/material_checks.h"
#include "scene/medium_grids.h"

namespace candela {

size_t Scene::triangleCount() const {
  size_t n = 0;
  for (const Instance& inst : instances) n += meshes[inst.meshId].triangleCount();
  return n;
}

size_t sceneMemoryBytes(const Scene& scene) {
  auto bytes = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
  size_t n = bytes(scene.instances) + bytes(scene.materials);
  for (const Mesh& m : scene.meshes)
    n += bytes(m.positions) + bytes(m.normals) + bytes(m.uvs) + bytes(m.tangents) + bytes(m.colors) + bytes(m.indices) +
         bytes(m.triangleMaterials) + bytes(m.curveVertices) + bytes(m.curveNormals) + bytes(m.curveSegments);
  for (const Texture& t : scene.textures) n += bytes(t.bytes) + bytes(t.floats);
  n += bytes(scene.mediumGrids) + bytes(scene.mediumGridValues);
  return n + bytes(scene.environment.map.floats);
}

namespace {

bool finite(Vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Whether every chain of mixes reaches a material of another type within kMaxMixDepth mixes (which a cycle never
// does). mixes[i] converges from below to the number of mixes the longest chain from material i passes: after
// round r it is exact wherever that number is at most r, and it exceeds r on longer chains and cycles.
bool mixChainsEnd(const std::vector<Material>& materials) {
  std::vector<uint32_t> mixes(materials.size(), 0);
  for (uint32_t round = 0; round <= kMaxMixDepth; ++round)
    for (size_t i = 0; i < materials.size(); ++i)
      if (materials[i].type == MaterialType::Mix)
        mixes[i] = 1 + std::max(mixes[materials[i].mixedMaterials[0]], mixes[materials[i].mixedMaterials[1]]);
  return std::all_of(mixes.begin(), mixes.end(), [](uint32_t n) { return n <= kMaxMixDepth; });
}

// What is wrong with a mesh's curves, or nothing: a mesh holds triangles or curves of one type, each segment's
// control points within curveVertices, radii finite and not negative, ribbons with a normal per control point.
std::string curveProblem(const Mesh& mesh, size_t materials) {
  if (mesh.curveSegments.empty())
    return mesh.curveVertices.empty() && mesh.curveNormals.empty() ? "" : "has curve vertices but no curve segments";
  if (!mesh.indices.empty()) return "holds both triangles and curves";
  const CurveType type = mesh.curveSegments[0].type;
  if (uint32_t(type) >= kCurveTypeCount) return "has a curve of unknown type";
  const bool ribbons = type == CurveType::Ribbon;
  if (ribbons ? mesh.curveNormals.size() != mesh.curveVertices.size() : !mesh.curveNormals.empty())
    return "needs one curve normal per control point of its ribbons, and none for other curves";
  for (const CurveSegment& segment : mesh.curveSegments) {
    if (segment.type != type) return "mixes curve types";
    if (segment.firstVertex > mesh.curveVertices.size() ||
        mesh.curveVertices.size() - segment.firstVertex < kCurveControlPoints)
      return "has a curve segment past its control points";
    if (segment.material >= materials) return "uses a missing material";
  }
  for (const Vec4& v : mesh.curveVertices)
    if (!finite(Vec3{v.x, v.y, v.z}) || !std::isfinite(v.w) || v.w < 0.0f)
      return "has a curve control point that is not finite or has a negative radius";
  for (Vec3 n : mesh.curveNormals)
    if (!finite(n)) return "has a non-finite curve normal";
  return "";
}

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
    if (!mesh.uvs.empty() && mesh.uvs.size() != mesh.positions.size())
      fail("mesh '" + mesh.name + "' has " + std::to_string(mesh.uvs.size()) + " texture coordinates for " +
           std::to_string(mesh.positions.size()) + " positions");
    if (!mesh.tangents.empty() && mesh.tangents.size() != mesh.positions.size())
      fail("mesh '" + mesh.name + "' has " + std::to_string(mesh.tangents.size()) + " tangents for " +
           std::to_string(mesh.positions.size()) + " positions");
    if (!mesh.colors.empty() && mesh.colors.size() != mesh.positions.size())
      fail("mesh '" + mesh.name + "' has " + std::to_string(mesh.colors.size()) + " vertex colours for " +
           std::to_string(mesh.positions.size()) + " positions");
    for (uint32_t index : mesh.indices)
      if (index >= mesh.positions.size()) fail("mesh '" + mesh.name + "' indexes past its vertices");
    for (uint32_t id : mesh.triangleMaterials)
      if (id >= scene.materials.size()) fail("mesh '" + mesh.name + "' uses a missing material");
    for (Vec3 p : mesh.positions)
      if (!finite(p)) fail("mesh '" + mesh.name + "' has a non-finite vertex position");
    if (std::string problem = curveProblem(mesh, scene.materials.size()); !problem.empty())
      fail("mesh '" + mesh.name + "' " + problem);
  }
  auto mediumExists = [&](uint32_t medium) { return medium == kNoMedium || medium < scene.media.size(); };
  for (const Instance& inst : scene.instances) {
    if (inst.meshId >= scene.meshes.size()) fail("an instance refers to a missing mesh");
    if (!mediumExists(inst.media.inside) || !mediumExists(inst.media.outside))
      fail("an instance bounds a missing medium");
  }
  if (!mediumExists(scene.cameraMedium)) fail("the camera is in a missing medium");
  auto nonNegative = [](Vec3 v) { return finite(v) && v.x >= 0.0f && v.y >= 0.0f && v.z >= 0.0f; };
  for (const Medium& m : scene.media)
    if (!nonNegative(m.sigmaA) || !nonNegative(m.sigmaS) || !nonNegative(m.emission) || !(std::fabs(m.g) < 1.0f))
      fail("a medium has negative or non-finite coefficients or emission, or |g| not below 1");
  for (const Medium& m : scene.media) {
    if (m.grid != kHomogeneous && m.grid >= scene.mediumGrids.size()) fail("a medium names a missing grid");
    if (m.subsurface > 1) fail("a medium's subsurface flag is neither 0 nor 1");
  }
  for (const MediumGrid& grid : scene.mediumGrids)
    if (std::string problem = mediumGridProblem(grid, scene.mediumGridValues); !problem.empty()) fail(problem);
  if (std::string problem = mediumGridValuesProblem(scene.mediumGridValues); !problem.empty()) fail(problem);
  bool anyMix = false;
  for (const Material& m : scene.materials) {
    if (std::string problem = materialMemberProblem(m, scene.textures.size()); !problem.empty()) fail(problem);
    if (m.type != MaterialType::Mix) continue;
    anyMix = true;
    if (m.mixedMaterials[0] >= scene.materials.size() || m.mixedMaterials[1] >= scene.materials.size())
      fail("a mix material mixes a missing material");
    if (!std::isfinite(m.mixAmount)) fail("a mix material has a non-finite amount");
  }
  if (anyMix && !mixChainsEnd(scene.materials))
    fail("mix materials nest more than " + std::to_string(kMaxMixDepth) + " deep or mix themselves");
  for (const PunctualLight& light : scene.punctualLights)
    if (!finite(light.position) || !finite(light.direction) || !finite(light.intensity))
      fail("a punctual light has non-finite parameters");
  for (const Texture& t : scene.textures) {
    size_t texels = size_t(t.width) * t.height * t.channels;
    if (t.width == 0 || t.height == 0 || t.channels < 1 || t.channels > 4)
      fail("texture '" + t.name + "' has no texels or an unsupported channel count");
    if (t.bytes.size() != texels && t.floats.size() != texels)
      fail("texture '" + t.name + "' holds the wrong number of values for its size");
  }
}

}  // namespace candela
