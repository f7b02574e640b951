#include "support/punctual_light_scenes.h"

#include <cmath>

#include "scene/mesh_builders.h"

namespace candela::test {

namespace {

Material grey(float albedo) {
  Material m;
  m.baseColor = {albedo, albedo, albedo};
  return m;
}

}  // namespace

Scene makePointLitSphere(float albedo, float intensity) {
  Scene scene;
  scene.name = "point-lit-sphere";
  scene.materials = {grey(albedo)};
  scene.meshes.push_back(makeUvSphere(1.0f, 256, 128, 0, /*inward=*/true));
  scene.meshes.back().normals.clear();  // the facets, as the light sees them
  scene.instances.push_back({0, Affine3x4{}});
  PunctualLight light;
  light.type = PunctualLightType::Point;
  light.intensity = {intensity, intensity, intensity};
  scene.punctualLights.push_back(light);
  scene.camera.eye = {0, 0, 0};
  scene.camera.target = {0, 0, 1};
  scene.camera.verticalFovDegrees = 90.0f;
  return scene;
}

Scene makeDirectionallyLitFloor(float albedo, float irradiance, float cosAngle) {
  Scene scene;
  scene.name = "directionally-lit-floor";
  scene.materials = {grey(albedo)};
  Mesh floor;
  appendQuad(floor, {-100, 0, -100}, {100, 0, -100}, {100, 0, 100}, {-100, 0, 100}, {0, 1, 0}, 0);
  scene.meshes.push_back(floor);
  scene.instances.push_back({0, Affine3x4{}});
  PunctualLight light;
  light.type = PunctualLightType::Directional;
  const float sinAngle = std::sqrt(1.0f - cosAngle * cosAngle);
  light.direction = {sinAngle, -cosAngle, 0.0f};
  light.intensity = {irradiance, irradiance, irradiance};
  scene.punctualLights.push_back(light);
  scene.camera.eye = {0, 5, 0};
  scene.camera.target = {0, 0, 0};
  scene.camera.up = {0, 0, 1};
  scene.camera.verticalFovDegrees = 40.0f;
  return scene;
}

Scene makeMixedFloor(float first, float second, float amount, std::optional<uint8_t> amountTexel, float irradiance,
                     float cosAngle) {
  Scene scene = makeDirectionallyLitFloor(first, irradiance, cosAngle);
  scene.name = "mixed-floor";
  Material mix;
  mix.type = MaterialType::Mix;
  mix.mixedMaterials[0] = 0;
  mix.mixedMaterials[1] = 1;
  mix.mixAmount = amount;
  if (amountTexel) {
    Texture texel;
    texel.name = "mix amount";
    texel.width = texel.height = texel.channels = 1;
    texel.bytes = {*amountTexel};
    scene.textures.push_back(texel);
    mix.mixAmountTexture = 0;
  }
  scene.materials = {grey(first), grey(second), mix};
  for (uint32_t& m : scene.meshes[0].triangleMaterials) m = 2;
  return scene;
}

}  // namespace candela::test
