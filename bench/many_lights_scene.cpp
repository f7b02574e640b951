#include "many_lights_scene.h"

#include <random>

#include "scene/mesh_builders.h"

namespace candela {

Scene makeNightTown(uint32_t blocks, uint32_t seed) {
  constexpr float kSpacing = 12.0f;  // block pitch, metres
  constexpr float kBuilding = 7.0f;  // building footprint
  constexpr float kLampHeight = 5.0f, kLampSize = 0.3f;
  constexpr float kWindowWidth = 0.9f, kWindowHeight = 1.2f;
  enum : uint32_t { kGround, kWall, kLamp, kWarmWindow, kColdWindow };
  Scene scene;
  scene.name = "night-town";
  scene.materials = {diffuseMaterial({0.35f, 0.35f, 0.35f}), diffuseMaterial({0.6f, 0.55f, 0.5f}),
                     diffuseMaterial({0.8f, 0.8f, 0.8f}, {400.0f, 300.0f, 160.0f}),
                     diffuseMaterial({0.8f, 0.8f, 0.8f}, {6.0f, 4.5f, 2.5f}),
                     diffuseMaterial({0.8f, 0.8f, 0.8f}, {2.5f, 3.5f, 5.0f})};
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  Mesh mesh;
  mesh.name = "town";
  const float half = 0.5f * kSpacing * float(blocks);
  const float groundHalf = half + 2.0f * kSpacing;
  appendQuad(mesh, {-groundHalf, 0, -groundHalf}, {groundHalf, 0, -groundHalf}, {groundHalf, 0, groundHalf},
             {-groundHalf, 0, groundHalf}, {0, 1, 0}, kGround);
  for (uint32_t i = 0; i < blocks; ++i)
    for (uint32_t j = 0; j < blocks; ++j) {
      Vec3 centre{-half + kSpacing * (float(i) + 0.5f), 0.0f, -half + kSpacing * (float(j) + 0.5f)};
      float height = 4.0f + 14.0f * unit(rng);
      const float r = 0.5f * kBuilding;
      const Vec3 floor[4] = {centre + Vec3{-r, 0, -r}, centre + Vec3{r, 0, -r}, centre + Vec3{r, 0, r},
                             centre + Vec3{-r, 0, r}};
      appendBlock(mesh, floor, height, kWall);
      // Two windows per wall, a few centimetres out from it, at random places on it.
      for (int wall = 0; wall < 4; ++wall) {
        Vec3 outward = wall == 0   ? Vec3{0, 0, -1}
                       : wall == 1 ? Vec3{0, 0, 1}
                       : wall == 2 ? Vec3{-1, 0, 0}
                                   : Vec3{1, 0, 0};
        Vec3 along = wall < 2 ? Vec3{1, 0, 0} : Vec3{0, 0, 1};
        for (int w = 0; w < 2; ++w) {
          float s = (unit(rng) - 0.5f) * (kBuilding - 2.0f * kWindowWidth);
          float y = 1.0f + unit(rng) * (height - 1.0f - 2.0f * kWindowHeight);
          Vec3 base = centre + outward * (0.5f * kBuilding + 0.02f) + along * s + Vec3{0, y, 0};
          Vec3 a = base - along * (0.5f * kWindowWidth), b = base + along * (0.5f * kWindowWidth);
          Vec3 up{0, kWindowHeight, 0};
          appendQuad(mesh, a, b, b + up, a + up, base + outward, unit(rng) < 0.7f ? kWarmWindow : kColdWindow);
        }
      }
    }
  // A lamp at every street crossing, shining down.
  for (uint32_t i = 0; i <= blocks; ++i)
    for (uint32_t j = 0; j <= blocks; ++j) {
      Vec3 c{-half + kSpacing * float(i), kLampHeight, -half + kSpacing * float(j)};
      float h = 0.5f * kLampSize;
      appendQuad(mesh, c + Vec3{-h, 0, -h}, c + Vec3{h, 0, -h}, c + Vec3{h, 0, h}, c + Vec3{-h, 0, h},
                 c - Vec3{0, 1, 0}, kLamp);
    }
  scene.meshes.push_back(std::move(mesh));
  scene.instances.push_back({0, Affine3x4{}});
  // Over a street at the town's edge, looking in along it and down onto the blocks.
  scene.camera.eye = {-half - 6.0f, 14.0f, -0.3f * half};
  scene.camera.target = {0.0f, 0.0f, 0.1f * half};
  scene.camera.verticalFovDegrees = 50.0f;
  return scene;
}

Scene makePointLitField(uint32_t lights, uint32_t seed) {
  constexpr float kHalf = 50.0f;   // the field is 100 m square
  constexpr float kPillar = 1.0f;  // half the side of a pillar
  enum : uint32_t { kGround, kPillarMaterial };
  Scene scene;
  scene.name = "point-field";
  scene.materials = {diffuseMaterial({0.4f, 0.4f, 0.4f}), diffuseMaterial({0.6f, 0.55f, 0.5f})};
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  Mesh mesh;
  mesh.name = "field";
  appendQuad(mesh, {-kHalf, 0, -kHalf}, {kHalf, 0, -kHalf}, {kHalf, 0, kHalf}, {-kHalf, 0, kHalf}, {0, 1, 0}, kGround);
  // Pillars on a 10 m grid, to cast the shadows that make some lights reach a point and others not.
  for (int i = -4; i <= 4; ++i)
    for (int j = -4; j <= 4; ++j) {
      Vec3 c{10.0f * float(i), 0.0f, 10.0f * float(j)};
      const Vec3 floor[4] = {c + Vec3{-kPillar, 0, -kPillar}, c + Vec3{kPillar, 0, -kPillar},
                             c + Vec3{kPillar, 0, kPillar}, c + Vec3{-kPillar, 0, kPillar}};
      appendBlock(mesh, floor, 2.0f + 4.0f * unit(rng), kPillarMaterial);
    }
  scene.meshes.push_back(std::move(mesh));
  scene.instances.push_back({0, Affine3x4{}});
  // Lamps of one intensity (so that picking by power picks uniformly) and random warm or cold tints.
  for (uint32_t i = 0; i < lights; ++i) {
    PunctualLight light;
    light.type = PunctualLightType::Point;
    light.position = {kHalf * (2.0f * unit(rng) - 1.0f), 0.3f + 1.2f * unit(rng), kHalf * (2.0f * unit(rng) - 1.0f)};
    light.intensity = unit(rng) < 0.7f ? Vec3{24.0f, 18.0f, 10.0f} : Vec3{10.0f, 16.0f, 26.0f};
    light.intensity = light.intensity * (1.0f / luminance(light.intensity));
    scene.punctualLights.push_back(light);
  }
  // From a corner above the field, looking across it.
  scene.camera.eye = {-kHalf - 5.0f, 12.0f, -kHalf * 0.4f};
  scene.camera.target = {0.0f, 0.0f, kHalf * 0.1f};
  scene.camera.verticalFovDegrees = 50.0f;
  return scene;
}

}  // namespace candela
