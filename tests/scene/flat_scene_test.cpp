#include <gtest/gtest.h>

#include "kernel/interaction.h"
#include "scene/flat_scene.h"

namespace candela {
namespace {

// An emissive triangle under a plain and a mirroring instance: the side the light table emits from must be the
// side kernel code sees as the front, or next-event estimation and hitting the light disagree.
TEST(FlatScene, LightTableAndInteractionAgreeOnTheFrontUnderMirroring) {
  Scene scene;
  Material lamp;
  lamp.emission = {1, 1, 1};
  scene.materials = {lamp};
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.indices = {0, 1, 2};
  m.triangleMaterials = {0};
  scene.meshes = {m};
  Affine3x4 mirror;
  mirror.m[0] = -1.0f;
  scene.instances = {{0, Affine3x4{}}, {0, mirror}};
  FlatScene flat = FlatScene::build(scene);
  SceneView view = flat.hostView();
  ASSERT_EQ(flat.lights.size(), 2u);
  for (uint32_t i = 0; i < 2; ++i) {
    Hit hit;
    hit.instanceId = i;
    hit.b1 = hit.b2 = 0.25f;
    Vec3 front = makeInteraction(view, hit, Ray{}).geometricNormal;
    Vec3 emitting = cross(flat.lights[i].edge1, flat.lights[i].edge2) * flat.lights[i].frontSign;
    EXPECT_GT(dot(front, emitting), 0.0f) << "instance " << i;
  }
}

// Posing the scene again keeps the punctual lights in the order kernel code reads them: the point and spot lights
// first (inside the light BVH), then the directional ones, whatever order the scene lists them in.
TEST(FlatScene, PosedAgainThePunctualLightsKeepTheirOrder) {
  Scene scene;
  scene.materials = {Material{}};
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.indices = {0, 1, 2};
  m.triangleMaterials = {0};
  scene.meshes = {m};
  scene.instances = {{0, Affine3x4{}}};
  PunctualLight sun, lamp;
  sun.type = PunctualLightType::Directional;
  sun.direction = {0, -1, 0};
  sun.intensity = {1, 1, 1};
  lamp.type = PunctualLightType::Point;
  lamp.position = {0, 2, 0};
  lamp.intensity = {1, 1, 1};
  scene.punctualLights = {sun, lamp};
  FlatScene flat = FlatScene::build(scene);
  ASSERT_EQ(flat.boundedPunctualLightCount, 1u);
  scene.instances[0].objectToWorld.m[3] = 1.0f;
  ASSERT_TRUE(flat.replaceInstanceTransforms(scene));
  ASSERT_EQ(flat.punctualLights.size(), 2u);
  EXPECT_EQ(flat.boundedPunctualLightCount, 1u);
  EXPECT_EQ(flat.punctualLights[0].type, PunctualLightType::Point);
  EXPECT_EQ(flat.punctualLights[1].type, PunctualLightType::Directional);
  EXPECT_EQ(flat.lightBvh.size(), 1u);  // the point light alone: the triangle does not emit
}

TEST(FlatScene, ConstantAndMapEnvironments) {
  Scene scene;
  scene.environment.radiance = {2, 2, 2};
  scene.environment.intensity = 0.5f;
  FlatScene constant = FlatScene::build(scene);
  EXPECT_FLOAT_EQ(constant.hostView().environment.scale.x, 1.0f);
  EXPECT_EQ(constant.hostView().environment.texels, nullptr);
  EXPECT_FLOAT_EQ(constant.environmentSelectProbability, 1.0f);

  scene.environment.map.width = 4;
  scene.environment.map.height = 2;
  scene.environment.map.channels = 3;
  scene.environment.map.floats.assign(4 * 2 * 3, 1.0f);
  scene.environment.visibleToCamera = false;
  FlatScene map = FlatScene::build(scene);
  SceneView v = map.hostView();
  ASSERT_NE(v.environment.texels, nullptr);
  EXPECT_FLOAT_EQ(environmentRadiance(v.environment, {0, 0, -1}).y, 0.5f);
  EXPECT_EQ(v.environment.visibleToCamera, 0u);

  scene.environment.map.floats.assign(4 * 2 * 3, 0.0f);  // a black map lights nothing and is never sampled
  EXPECT_FLOAT_EQ(FlatScene::build(scene).environmentSelectProbability, 0.0f);
}

}  // namespace
}  // namespace candela
