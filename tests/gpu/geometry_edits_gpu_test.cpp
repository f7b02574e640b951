// Scene updates on the OptiX backend rebuild only the acceleration structures of what changed, and give the
// images a fresh backend gives: with the same seed both trace the same paths, so any structure kept that no
// longer fits the scene changes the image.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>

#include "gpu_render.h"
#include "kernel/pass_through.h"
#include "support/scene_edits.h"

namespace candela {
namespace {

constexpr uint32_t kSize = 48;
constexpr uint32_t kSamples = 4;

Image renderWith(OptixBackend& backend) {
  backend.setSettings(test::squareImage(kSize, 23));
  backend.setCamera(makeMaterialGallery().camera.toCamera(1.0f));
  backend.render(kSamples);
  return backend.readImage();
}

Image renderFresh(const Scene& scene) {
  OptixBackend backend;
  backend.setScene(scene);
  return renderWith(backend);
}

// Whether two meshes have equal triangles for traversal: positions, indices, and which materials use alpha or
// cull back faces (they get their own geometry flags).
bool equalTriangles(const Scene& scene, const Mesh& a, const Mesh& b) {
  auto sameBytes = [](const auto& x, const auto& y) {
    return x.size() == y.size() && std::memcmp(x.data(), y.data(), x.size() * sizeof(x[0])) == 0;
  };
  if (!sameBytes(a.positions, b.positions) || !sameBytes(a.indices, b.indices)) return false;
  for (size_t t = 0; t < a.triangleMaterials.size(); ++t) {
    const Material &ma = scene.materials[a.triangleMaterials[t]], &mb = scene.materials[b.triangleMaterials[t]];
    if (usesAlpha(ma) != usesAlpha(mb) || cullsBackFaces(ma) != cullsBackFaces(mb)) return false;
  }
  return true;
}

// The GASes a scene needs: one per set of meshes with equal triangles, among those `counted` accepts.
template <class Counted>
uint64_t distinctMeshes(const Scene& scene, Counted&& counted) {
  uint64_t count = 0;
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    const Mesh& mesh = scene.meshes[m];
    if (mesh.triangleCount() == 0 || !counted(mesh)) continue;
    bool seen = false;
    for (size_t e = 0; e < m && !seen; ++e)
      seen = counted(scene.meshes[e]) && equalTriangles(scene, scene.meshes[e], mesh);
    if (!seen) ++count;
  }
  return count;
}

// Checks that `edited`, set after `before`, builds `meshBuilds` GASes and `instanceBuilds` IASes, and renders
// as a fresh backend renders it.
void expectUpdate(OptixBackend& backend, const Scene& edited, uint64_t meshBuilds, uint64_t instanceBuilds) {
  const AccelerationStatistics before = backend.accelerationStatistics();
  backend.setScene(edited);
  const AccelerationStatistics after = backend.accelerationStatistics();
  EXPECT_EQ(after.meshBuilds - before.meshBuilds, meshBuilds);
  EXPECT_EQ(after.instanceBuilds - before.instanceBuilds, instanceBuilds);
  test::expectSameImage(renderWith(backend), renderFresh(edited));
}

TEST(GpuGeometryEdits, SetSceneRebuildsOnlyWhatChanged) {
  const Scene original = makeMaterialGallery();
  ASSERT_GT(original.meshes.size(), 3u);
  ASSERT_GT(original.instances.size(), 3u);
  OptixBackend backend;
  backend.setScene(original);
  EXPECT_EQ(backend.accelerationStatistics().meshBuilds, distinctMeshes(original, [](const Mesh&) { return true; }));
  EXPECT_EQ(backend.accelerationStatistics().instanceBuilds, 1u);
  const Image unedited = renderWith(backend);
  {
    SCOPED_TRACE("the same scene again");
    expectUpdate(backend, original, 0, 0);
  }
  Scene reshaped = original;
  for (Vec3& p : reshaped.meshes[2].positions) p.x += 0.25f * p.y;
  {
    SCOPED_TRACE("one mesh's vertices moved");
    expectUpdate(backend, reshaped, 1, 1);
  }
  Scene moved = reshaped;
  moved.instances[3].objectToWorld.m[7] += 0.2f;
  {
    SCOPED_TRACE("one instance moved");
    expectUpdate(backend, moved, 0, 1);
  }
  Scene reordered = moved;
  std::reverse(reordered.meshes.begin(), reordered.meshes.end());
  for (Instance& instance : reordered.instances)
    instance.meshId = uint32_t(reordered.meshes.size()) - 1 - instance.meshId;
  {
    SCOPED_TRACE("the meshes in reverse order");
    expectUpdate(backend, reordered, 0, 0);
  }
  // The edits must have changed the picture, or the comparisons prove nothing.
  const Image edited = renderFresh(moved);
  EXPECT_NE(std::memcmp(unedited.pixels.data(), edited.pixels.data(), edited.pixels.size() * sizeof(Vec3)), 0);
}

// A material that becomes a cut-out needs any-hit on its triangles: setMaterials rebuilds the GASes of the
// meshes that use it and no others, and renders as setScene with the edited materials does.
TEST(GpuGeometryEdits, SetMaterialsRebuildsTheMeshesOfNewCutouts) {
  const Scene original = makeMaterialGallery();
  const uint32_t materialId = original.meshes[2].triangleMaterials[0];
  Scene edited = original;
  edited.materials[materialId].alphaMode = AlphaMode::Blend;
  edited.materials[materialId].opacity = 0.3f;
  const uint64_t users = distinctMeshes(edited, [&](const Mesh& mesh) {
    return std::find(mesh.triangleMaterials.begin(), mesh.triangleMaterials.end(), materialId) !=
           mesh.triangleMaterials.end();
  });
  ASSERT_GT(users, 0u);

  OptixBackend backend;
  backend.setScene(original);
  const AccelerationStatistics before = backend.accelerationStatistics();
  ASSERT_TRUE(backend.setMaterials(edited.materials));
  const AccelerationStatistics after = backend.accelerationStatistics();
  EXPECT_EQ(after.meshBuilds - before.meshBuilds, users);
  EXPECT_EQ(after.instanceBuilds - before.instanceBuilds, 1u);
  test::expectSameImage(renderWith(backend), renderFresh(edited));

  // A change that leaves every material's cut-out status alone rebuilds nothing.
  edited.materials[materialId].opacity = 0.6f;
  ASSERT_TRUE(backend.setMaterials(edited.materials));
  EXPECT_EQ(backend.accelerationStatistics().meshBuilds, after.meshBuilds);
  EXPECT_EQ(backend.accelerationStatistics().instanceBuilds, after.instanceBuilds);
  test::expectSameImage(renderWith(backend), renderFresh(edited));
}

}  // namespace
}  // namespace candela
