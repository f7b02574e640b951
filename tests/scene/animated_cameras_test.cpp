// Cameras and KHR_lights_punctual lights below animated glTF nodes follow the animation: their poses at given
// times against hand-computed ones, through scene files, camera choice, the scene's repair and the scene cache,
// and renders of a moving light.
#include <gtest/gtest.h>

#include <cmath>

#include "app/scene_loading.h"
#include "backends/cpu/cpu_backend.h"
#include "scene/animation_player.h"
#include "scene/cache/scene_cache.h"
#include "scene/gltf_cache_round_trip.h"
#include "scene/loaders/gltf/gltf_loader.h"
#include "scene/scene_test_files.h"
#include "support/animated_gltf.h"
#include "support/image_expectations.h"
#include "support/vector_expectations.h"

namespace candela {
namespace {

using test::AnimatedFile;
using test::kSqrtHalf;
using test::TempFolder;

using test::expectNear;

// AnimatedFile with its camera (node 2, at (0, 0, 10)) moved below node 0, which "Move" translates and turns, and a
// spot light (node 3) below node 0 too: at (0, 0, 3), turned 90 degrees about x so that it shines along +y at rest.
// A second light, not animated, sits beyond the coordinate range (the repair drops it) before the animated one.
AnimatedFile cameraAndLightBelowTheMovingNode() {
  AnimatedFile file;
  file.gltf["nodes"][0]["children"] = {1, 2, 3};
  file.gltf["nodes"].push_back({{"translation", {0, 0, 3}},
                                {"rotation", {kSqrtHalf, 0, 0, kSqrtHalf}},
                                {"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}});
  file.gltf["nodes"].push_back(
      {{"translation", {0, 0, 1e9}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  file.gltf["scenes"][0]["nodes"] = {4, 0};
  file.gltf["extensionsUsed"] = {"KHR_lights_punctual"};
  file.gltf["extensions"]["KHR_lights_punctual"]["lights"] = {
      {{"type", "point"}, {"intensity", 1}}, {{"type", "spot"}, {"intensity", 5}, {"spot", {{"outerConeAngle", 0.5}}}}};
  return file;
}

TEST(AnimatedCameras, ACameraBelowAnAnimatedNodeFollowsIt) {
  TempFolder folder;
  Scene scene = loadScene(cameraAndLightBelowTheMovingNode().write(folder.path()), SceneLoadOptions{});
  ASSERT_EQ(scene.cameras.size(), 1u);
  ASSERT_EQ(scene.animation.cameras.size(), 1u);
  EXPECT_EQ(scene.cameraIndex, 0);
  EXPECT_TRUE(sceneCameraAnimated(scene));
  expectNear(scene.camera.eye, {0, 0, 10});  // the rest pose

  const AnimationPlayer player(scene);
  // 1 s: node 0 at (2, 0, 0), turned 45 degrees about z: the camera's +y turns with it, its -z does not.
  player.pose(scene, 0, 1.0f);
  expectNear(scene.camera.eye, {2, 0, 10});
  expectNear(scene.camera.target, {2, 0, 9});
  expectNear(scene.camera.up, {-kSqrtHalf, kSqrtHalf, 0});
  EXPECT_EQ(scene.camera.verticalFovDegrees, scene.cameras[0].description.verticalFovDegrees);
  expectNear(scene.cameras[0].description.eye, scene.camera.eye, 0.0f);
  // 2 s: at (2, 4, 0), turned 90 degrees.
  player.pose(scene, 0, 2.0f);
  expectNear(scene.camera.eye, {2, 4, 10});
  expectNear(scene.camera.up, {-1, 0, 0});
  player.pose(scene, -1, 2.0f);
  expectNear(scene.camera.eye, {0, 0, 10});
  expectNear(scene.camera.up, {0, 1, 0});
}

TEST(AnimatedCameras, ALightBelowAnAnimatedNodeFollowsItAfterTheRepairDroppedAnother) {
  TempFolder folder;
  Scene scene = loadScene(cameraAndLightBelowTheMovingNode().write(folder.path()), SceneLoadOptions{});
  ASSERT_EQ(scene.punctualLights.size(), 1u);  // the light beyond the range is gone
  ASSERT_EQ(scene.animation.lights.size(), 1u);
  EXPECT_EQ(scene.animation.lights[0].light, 0u);
  EXPECT_EQ(scene.punctualLights[0].type, PunctualLightType::Spot);
  expectNear(scene.punctualLights[0].position, {0, 0, 3});
  expectNear(scene.punctualLights[0].direction, {0, 1, 0});

  const AnimationPlayer player(scene);
  player.pose(scene, 0, 2.0f);  // at (2, 4, 0), turned 90 degrees about z: +y becomes -x
  expectNear(scene.punctualLights[0].position, {2, 4, 3});
  expectNear(scene.punctualLights[0].direction, {-1, 0, 0});
  expectNear(scene.punctualLights[0].intensity, {5, 5, 5});
}

TEST(AnimatedCameras, ALightPosedOutOfRangeIsSwitchedOffAndComesBack) {
  TempFolder folder;
  AnimatedFile file = cameraAndLightBelowTheMovingNode();
  file.gltf["animations"][0]["samplers"][0]["output"] = file.add({0, 0, 0, 2e8f, 0, 0, 0, 0, 0}, "VEC3");
  Scene scene = loadScene(file.write(folder.path()), SceneLoadOptions{});
  const AnimationPlayer player(scene);
  player.pose(scene, 0, 1.0f);
  expectNear(scene.punctualLights[0].intensity, {0, 0, 0});
  expectNear(scene.punctualLights[0].position, {0, 0, 3});  // kept where it is at rest
  expectNear(scene.camera.eye, {0, 0, 10});                 // the camera too: its rest pose
  player.pose(scene, 0, 2.0f);
  expectNear(scene.punctualLights[0].intensity, {5, 5, 5});
}

TEST(AnimatedCameras, SceneFileCamerasAreRenumberedAndTheChosenOneFollows) {
  TempFolder folder;
  cameraAndLightBelowTheMovingNode().write(folder.path());
  const std::string path = folder.write("scene.json", R"({"camera": {"position": [0, 0, 30], "target": [0, 0, 0]},
      "models": [{"file": "animated.gltf", "transform": {"translate": [0, 0, -5]}},
                 {"file": "animated.gltf"}]})");
  {
    Scene scene = loadScene(path, SceneLoadOptions{});
    ASSERT_EQ(scene.cameras.size(), 2u);  // the file's own, then the model's (placed once)
    ASSERT_EQ(scene.animation.cameras.size(), 1u);
    EXPECT_EQ(scene.animation.cameras[0].camera, 1u);
    EXPECT_EQ(scene.animation.lights.size(), 1u);
    EXPECT_EQ(scene.animation.instances.size(), 2u);
    EXPECT_EQ(scene.cameraIndex, 0);
    EXPECT_FALSE(sceneCameraAnimated(scene));
    AnimationPlayer(scene).pose(scene, 0, 2.0f);
    expectNear(scene.camera.eye, {0, 0, 30});  // the scene file's camera stays
    expectNear(scene.cameras[1].description.eye, {2, 4, 5});
  }
  SceneLoadOptions options;
  options.camera = "1";
  Scene scene = loadScene(path, options);
  EXPECT_EQ(scene.cameraIndex, 1);
  EXPECT_TRUE(sceneCameraAnimated(scene));
  AnimationPlayer(scene).pose(scene, 0, 2.0f);
  expectNear(scene.camera.eye, {2, 4, 5});
}

TEST(AnimatedCameras, TheSceneCacheKeepsAnimatedCamerasAndLights) {
  TempFolder folder;
  const test::GltfCacheRoundTrip cache(folder, cameraAndLightBelowTheMovingNode().write(folder.path()));
  const Scene& scene = cache.loaded();
  CachedScene read;
  ASSERT_EQ(cache.writeAndRead(scene, read), SceneCacheRead::Hit);
  EXPECT_EQ(read.scene.cameraIndex, 0);
  ASSERT_EQ(read.scene.animation.cameras.size(), 1u);
  ASSERT_EQ(read.scene.animation.lights.size(), 1u);
  EXPECT_EQ(read.scene.animation.lights[0].light, scene.animation.lights[0].light);

  Scene broken = scene;
  broken.animation.lights[0].light = 9;
  EXPECT_EQ(cache.refusal(broken), "an animated light refers to a missing light or node");
  broken = scene;
  broken.cameraIndex = 1;
  EXPECT_EQ(cache.refusal(broken), "the scene's camera is not one of its cameras");
}

// A dark quad lit by a point light that "Move" carries: setInstanceTransforms must move the light as a full
// setScene of the posed scene does.
TEST(AnimatedCameras, AMovingLightRendersAsAFullSceneRebuildDoes) {
  TempFolder folder;
  AnimatedFile file;
  file.gltf["materials"] = {
      {{"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.8, 0.8, 1}}, {"metallicFactor", 0}}}}};
  // Node 0 carries the light (at (-2, -1, 1) below it) and slides along x by 4 over 1 s; node 1 is a wide floor.
  file.gltf["nodes"] = {{{"children", {2}}},
                        {{"mesh", 0}, {"scale", {8, 8, 1}}},
                        {{"translation", {-2, -1, 1}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}},
                        {{"camera", 0}, {"translation", {0, 0, 10}}}};
  file.gltf["scenes"][0]["nodes"] = {0, 1, 3};
  file.gltf["extensionsUsed"] = {"KHR_lights_punctual"};
  file.gltf["extensions"]["KHR_lights_punctual"]["lights"] = {{{"type", "point"}, {"intensity", 20}}};
  file.gltf["animations"][0]["samplers"][0]["output"] = file.add({0, 0, 0, 4, 0, 0, 4, 0, 0}, "VEC3");
  file.gltf["animations"][0]["channels"] = {file.gltf["animations"][0]["channels"][0]};
  Scene scene = loadScene(file.write(folder.path()), SceneLoadOptions{});
  ASSERT_EQ(scene.animation.lights.size(), 1u);
  const AnimationPlayer player(scene);
  RenderSettings settings;
  settings.width = 32;
  settings.height = 24;
  settings.seed = 5;
  const Camera camera = scene.camera.toCamera(32.0f / 24.0f);
  auto start = [&](CpuBackend& backend) {
    backend.setSettings(settings);
    backend.setCamera(camera);
  };
  CpuBackend moved;
  moved.setScene(scene);
  start(moved);
  moved.render(1);
  const Image atRest = moved.readImage();
  player.pose(scene, 0, 1.0f);
  moved.setInstanceTransforms(scene);
  moved.render(1);
  const Image posed = moved.readImage();
  CpuBackend rebuilt;
  rebuilt.setScene(scene);
  start(rebuilt);
  rebuilt.render(1);
  const Image expected = rebuilt.readImage();
  test::expectRebuiltImageThatChanged(posed, expected, atRest, 1.0);
}

}  // namespace
}  // namespace candela
