#include "support/many_small_lights.h"

#include "core/rng.h"
#include "scene/mesh_builders.h"

namespace candela::test {

Scene makeManySmallLights(uint32_t lights, uint32_t seed) {
  Scene scene;
  scene.name = "many-small-lights";
  scene.materials.push_back(diffuseMaterial({0.6f, 0.6f, 0.6f}));
  Mesh ground;
  appendQuad(ground, {-10, 0, -10}, {10, 0, -10}, {10, 0, 10}, {-10, 0, 10}, {0, 1, 0}, 0);
  for (int i = 0; i < 4; ++i) {
    const float x = -5.0f + 3.3f * float(i), z = float(i % 2) * 2.0f - 1.0f;
    const Vec3 base[4] = {{x, 0, z}, {x + 1.2f, 0, z}, {x + 1.2f, 0, z + 1.2f}, {x, 0, z + 1.2f}};
    appendBlock(ground, base, 1.5f + 0.5f * float(i), 0);
  }
  scene.meshes.push_back(ground);
  scene.instances.push_back({0, Affine3x4{}});

  Mesh emitters;
  for (uint32_t i = 0; i < lights; ++i) {
    auto u = [&](uint32_t d) { return randomUniform(i, d, 0, seed); };
    const Vec3 colour{0.4f + 0.6f * u(0), 0.4f + 0.6f * u(1), 0.4f + 0.6f * u(2)};
    scene.materials.push_back(diffuseMaterial({0, 0, 0}, colour * (20.0f + 60.0f * u(3))));
    const float x = -9.0f + 18.0f * u(4), z = -9.0f + 18.0f * u(5), y = 2.5f + 3.0f * u(6);
    const float h = 0.04f + 0.08f * u(7);
    appendQuad(emitters, {x - h, y, z - h}, {x + h, y, z - h}, {x + h, y, z + h}, {x - h, y, z + h}, {0, -1, 0},
               uint32_t(scene.materials.size() - 1));
  }
  scene.meshes.push_back(emitters);
  scene.instances.push_back({1, Affine3x4{}});
  scene.camera.eye = {0, 9, 11};
  scene.camera.target = {0, 0, 0};
  scene.camera.verticalFovDegrees = 50.0f;
  return scene;
}

}  // namespace candela::test
