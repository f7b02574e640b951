// Scene updates on the OptiX backend rebuild only the acceleration structures of what changed, and give the
// images a fresh backend gives: with the same seed both trace the same paths, so any structure kept that no
// longer fits the scene changes the image.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>

#include "gpu_render.h"
#include "kernel/pass_through.h"

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

void expectSameImage(const Image& a, const Image& b) {
  ASSERT_EQ(a.pixels.size(), b.pixels.size());
  size_t differing = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i)
    if (std::memcmp(&a.pixels[i], &b.pixels[i], sizeof(Vec3)) != 0) ++differing;
  EXPECT_EQ(differing, 0u) << "of " << a.pixels.size() << " pixels";
}

uint64_t meshesWithTriangles(const Scene& scene) {
  return uint64_t(std::count_if(scene.meshes.begin(), scene.meshes.end(),
                                [](const Mesh& m) { return m.triangleCount() > 0; }));
}

// Checks that `edited`, set after `before`, builds `meshBuilds` GASes and `instanceBuilds` IASes, and renders
// as a fresh backend renders it.
void expectUpdate(OptixBackend& backend, const Scene& edited, uint64_t meshBuilds, uint64_t instanceBuilds) {
  const AccelerationStatistics before = backend.accelerationStatistics();
  backend.setScene(edited);
  const AccelerationStatistics after = backend.accelerationStatistics();
  EXPECT_EQ(after.meshBuilds - before.meshBuilds, meshBuilds);
  EXPECT_EQ(after.instanceBuilds - before.instanceBuilds, instanceBuilds);
  expectSameImage(renderWith(backend), renderFresh(edited));
}

TEST(GpuGeometryEdits, SetSceneRebuildsOnlyWhatChanged) {
  const Scene original = makeMaterialGallery();
  ASSERT_GT(original.meshes.size(), 3u);
  ASSERT_GT(original.instances.size(), 3u);
  OptixBackend backend;
  backend.setScene(original);
  EXPECT_EQ(backend.accelerationStatistics().meshBuilds, meshesWithTriangles(original));
  EXPECT_EQ(backend.accelerationStatistics().instanceBuilds, 1u);
  const Image unedited = renderWith(backend);
  {
    SCOPED_TRACE("the same scene again");
    expectUpdate(backend, original, 0, 0);
  }
  Scene shrunk = original;
  for (Vec3& p : shrunk.meshes[2].positions) p = p * 0.5f;
  {
    SCOPED_TRACE("one mesh's vertices moved");
    expectUpdate(backend, shrunk, 1, 1);
  }
  Scene moved = shrunk;
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
  uint64_t users = 0;
  for (const Mesh& mesh : original.meshes)
    if (std::find(mesh.triangleMaterials.begin(), mesh.triangleMaterials.end(), materialId) !=
        mesh.triangleMaterials.end())
      ++users;
  Scene edited = original;
  edited.materials[materialId].alphaMode = AlphaMode::Blend;
  edited.materials[materialId].opacity = 0.3f;
  ASSERT_TRUE(canPassThrough(edited.materials[materialId]));

  OptixBackend backend;
  backend.setScene(original);
  const AccelerationStatistics before = backend.accelerationStatistics();
  ASSERT_TRUE(backend.setMaterials(edited.materials));
  const AccelerationStatistics after = backend.accelerationStatistics();
  EXPECT_EQ(after.meshBuilds - before.meshBuilds, users);
  EXPECT_EQ(after.instanceBuilds - before.instanceBuilds, 1u);
  expectSameImage(renderWith(backend), renderFresh(edited));

  // A change that leaves every material's cut-out status alone rebuilds nothing.
  edited.materials[materialId].opacity = 0.6f;
  ASSERT_TRUE(backend.setMaterials(edited.materials));
  EXPECT_EQ(backend.accelerationStatistics().meshBuilds, after.meshBuilds);
  EXPECT_EQ(backend.accelerationStatistics().instanceBuilds, after.instanceBuilds);
  expectSameImage(renderWith(backend), renderFresh(edited));
}

}  // namespace
}  // namespace candela
