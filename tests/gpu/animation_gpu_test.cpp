// Animated scenes on the OptiX backend: frames posed through setInstanceTransforms (the IAS built again over the
// kept GASes, the instance records, light tables and punctual lights uploaded again) equal, bit for bit, frames of
// a fresh backend given the posed scene with setScene.
#include <gtest/gtest.h>

#include <cstring>

#include "gpu_render.h"
#include "scene/animation_player.h"
#include "scene/loaders/gltf/gltf_loader.h"
#include "scene/mesh_builders.h"
#include "scene/scene_test_files.h"
#include "support/animated_gltf.h"
#include "support/scene_edits.h"

namespace candela {
namespace {

constexpr uint32_t kSize = 48;
constexpr uint32_t kSamples = 4;

Image renderWith(OptixBackend& backend, const Scene& scene) {
  backend.setSettings(test::squareImage(kSize, 31));
  backend.setCamera(scene.camera.toCamera(1.0f));
  backend.render(kSamples);
  return backend.readImage();
}

Image renderFresh(const Scene& scene) {
  OptixBackend backend;
  backend.setScene(scene);
  return renderWith(backend, scene);
}

bool sameImage(const Image& a, const Image& b) {
  return a.pixels.size() == b.pixels.size() &&
         std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(Vec3)) == 0;
}

// The animation tests' glTF (tests/support/animated_gltf.h): its emissive quad moved and turned by "Move", over a
// grey floor, with a point light that node 0 carries too.
Scene animatedScene(const test::TempFolder& folder) {
  test::AnimatedFile file;
  file.gltf["materials"].push_back({{"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.8, 0.8, 1}}}}});
  file.gltf["meshes"].push_back(file.gltf["meshes"][0]);
  file.gltf["meshes"][1]["primitives"][0]["material"] = 1;
  file.gltf["nodes"][0]["children"] = {1, 3};
  file.gltf["nodes"].push_back(
      {{"translation", {1, -1, 2}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  file.gltf["nodes"].push_back({{"mesh", 1}, {"translation", {0, 0, -1}}, {"scale", {12, 12, 1}}});
  file.gltf["scenes"][0]["nodes"] = {0, 2, 4};
  file.gltf["extensionsUsed"] = {"KHR_lights_punctual"};
  file.gltf["extensions"]["KHR_lights_punctual"]["lights"] = {{{"type", "point"}, {"intensity", 30}}};
  LoadWarnings warnings;
  return loadGltf(file.write(folder.path()), warnings);
}

TEST(GpuAnimation, FramesThroughSetInstanceTransformsEqualFullRebuilds) {
  test::TempFolder folder;
  Scene scene = animatedScene(folder);
  ASSERT_EQ(scene.animation.lights.size(), 1u);
  const AnimationPlayer player(scene);
  OptixBackend animated;
  animated.setScene(scene);
  const AccelerationStatistics loaded = animated.accelerationStatistics();
  const Image atRest = renderWith(animated, scene);
  uint64_t frames = 0;
  for (float time : {0.25f, 1.0f, 1.5f}) {
    SCOPED_TRACE(time);
    player.pose(scene, 0, time);
    animated.setInstanceTransforms(scene);
    ++frames;
    const Image frame = renderWith(animated, scene);
    test::expectSameImage(frame, renderFresh(scene));
    EXPECT_FALSE(sameImage(frame, atRest));
    const AccelerationStatistics now = animated.accelerationStatistics();
    EXPECT_EQ(now.meshBuilds, loaded.meshBuilds);  // every GAS kept
    EXPECT_EQ(now.instanceBuilds, loaded.instanceBuilds + frames);
  }
}

// Enough meshes of one instance each that setScene builds them in batches, in world space: a pose must build the
// batches again (and only them).
TEST(GpuAnimation, BatchedMeshesAreBuiltAgainWithTheirInstances) {
  Scene scene;
  Material grey;
  grey.baseColor = {0.7f, 0.7f, 0.7f};
  Material glowing;
  glowing.emission = {4, 3, 2};
  scene.materials = {grey, glowing};
  constexpr int kSide = 18;  // 324 meshes
  for (int i = 0; i < kSide * kSide; ++i) {
    Mesh mesh;
    const float x = float(i % kSide) - kSide / 2.0f, y = float(i / kSide) - kSide / 2.0f, h = 0.3f + 0.001f * float(i);
    appendQuad(mesh, {x, y, 0}, {x + h, y, 0}, {x + h, y + h, 0}, {x, y + h, 0}, {0, 0, 1}, i % 7 == 0 ? 1 : 0);
    scene.meshes.push_back(std::move(mesh));
    scene.instances.push_back({uint32_t(i), Affine3x4{}});
  }
  scene.environment.radiance = {0.2f, 0.2f, 0.3f};
  scene.camera.eye = {0, 0, 20};
  scene.camera.target = {0, 0, 0};
  OptixBackend animated;
  animated.setScene(scene);
  const AccelerationStatistics loaded = animated.accelerationStatistics();
  ASSERT_GT(loaded.batchedMeshes, 0u);
  const Image atRest = renderWith(animated, scene);
  for (Instance& instance : scene.instances) {
    instance.objectToWorld.m[3] += 0.4f;
    instance.objectToWorld.m[7] -= 0.25f;
  }
  animated.setInstanceTransforms(scene);
  const AccelerationStatistics posed = animated.accelerationStatistics();
  EXPECT_EQ(posed.batchedMeshes - loaded.batchedMeshes, loaded.batchedMeshes);
  EXPECT_EQ(posed.meshBuilds - loaded.meshBuilds, loaded.batchedMeshes);
  const Image frame = renderWith(animated, scene);
  test::expectSameImage(frame, renderFresh(scene));
  EXPECT_FALSE(sameImage(frame, atRest));
}

}  // namespace
}  // namespace candela
