// DeviceScene copies every array of kernel/scene_arrays.h to the device and points its view at the copies: each
// check here is generated from the list, so an array added to it is checked without a change here.
#include <cuda_runtime.h>
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "backends/optix/device_scene.h"
#include "kernel/scene_arrays.h"

namespace candela {
namespace {

// Two triangles with every per-mesh array, one of them a lamp, a ribbon curve, a point light, and a grid medium
// behind the second triangle: no listed array is empty.
Scene sceneWithEveryArray() {
  Scene scene;
  Material lamp;
  lamp.emission = {2, 2, 2};
  scene.materials = {lamp, Material{}};
  for (uint32_t k = 0; k < 2; ++k) {
    const float f = float(k);
    Mesh m;
    m.positions = {{f, 0, 0}, {f + 1, 0, 0}, {f, 1, 0}};
    m.normals = {{0, 0, 1}, {0, 0.6f, 0.8f}, {0, 0.8f, 0.6f}};
    m.uvs = {{f, 0}, {1, f}, {0, 1}};
    m.tangents = {{1, 0, 0, 1}, {1, 0, 0, -1}, {0, 1, 0, 1}};
    m.colors = {{f, 0.5f, 0.25f}, {0.125f, f, 1}, {1, 1, f}};
    m.indices = {0, 1, 2};
    m.triangleMaterials = {k};
    scene.meshes.push_back(m);
  }
  Mesh ribbon;  // a curve segment with normals
  for (int i = 0; i < 4; ++i) ribbon.curveVertices.push_back({float(i), 2, 0, 0.1f});
  ribbon.curveNormals.assign(4, Vec3{0, 0, -1});
  ribbon.curveSegments.push_back({0, 1, CurveType::Ribbon});
  scene.meshes.push_back(ribbon);
  scene.instances = {{0, Affine3x4{}}, {1, Affine3x4{}}, {2, Affine3x4{}}};
  Medium fog;
  fog.sigmaA = {0.1f, 0.1f, 0.1f};
  fog.sigmaS = {0.5f, 0.5f, 0.5f};
  fog.grid = 0;
  MediumGrid grid;  // one density sample and its majorant
  grid.density = 0;
  grid.majorants = 1;
  scene.media = {fog};
  scene.mediumGrids = {grid};
  scene.mediumGridValues = {0.5f, 0.5f};
  scene.instances[1].media.inside = 0;
  PunctualLight light;
  light.position = {0, 2, 0};
  light.intensity = {1, 1, 1};
  scene.punctualLights = {light};
  return scene;
}

template <class T>
void expectOnTheDevice(const T* device, const std::vector<T>& host, const char* member) {
  ASSERT_NE(device, nullptr) << member;
  std::vector<T> copy(host.size());
  ASSERT_EQ(cudaMemcpy(copy.data(), device, host.size() * sizeof(T), cudaMemcpyDeviceToHost), cudaSuccess) << member;
  EXPECT_EQ(std::memcmp(copy.data(), host.data(), host.size() * sizeof(T)), 0) << member;
}

void expectCount(const SceneView&, std::nullptr_t, size_t, const char*) {}
void expectCount(const SceneView& view, uint32_t SceneView::*count, size_t size, const char* member) {
  EXPECT_EQ(view.*count, size) << member;
}

void expectEveryArrayOnTheDevice(const FlatScene& flat, const SceneView& view) {
#define CANDELA_EXPECT_ON_THE_DEVICE(Type, member, upload, count, description)  \
  ASSERT_FALSE(flat.member.empty()) << "sceneWithEveryArray gives no " #member; \
  expectOnTheDevice(view.member, flat.member, #member);                         \
  expectCount(view, CANDELA_SCENE_ARRAY_COUNT_FIELD(count), flat.member.size(), #member);
  CANDELA_SCENE_ARRAYS(CANDELA_EXPECT_ON_THE_DEVICE)
#undef CANDELA_EXPECT_ON_THE_DEVICE
}

TEST(DeviceScene, EveryListedArrayIsOnTheDeviceAfterEachUpdate) {
  Scene scene = sceneWithEveryArray();
  FlatScene flat = FlatScene::build(scene);
  optix::DeviceScene device;
  device.upload(flat);
  expectEveryArrayOnTheDevice(flat, device.view());

  std::vector<Material> materials = scene.materials;
  materials[1].baseColor = {0.25f, 0.5f, 0.75f};
  ASSERT_TRUE(flat.replaceMaterials(materials));
  device.updateMaterials(flat);
  expectEveryArrayOnTheDevice(flat, device.view());

  scene.instances[1].objectToWorld.m[3] = 2.0f;
  scene.instances[0].objectToWorld.m[7] = 0.5f;
  ASSERT_TRUE(flat.replaceInstanceTransforms(scene));
  device.updateInstances(flat);
  expectEveryArrayOnTheDevice(flat, device.view());
}

}  // namespace
}  // namespace candela
