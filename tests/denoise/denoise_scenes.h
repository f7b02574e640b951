#pragma once
// Scenes for the denoising quality tests with what breaks a denoiser that smooths emitted or very bright light: a
// black emitter of high radiance, a tiny very bright emitter in view, an emissive texture, an HDR sky with a sun,
// a glossy floor reflecting the light.
#include <cmath>
#include <utility>

#include "scene/builtin_scenes.h"
#include "scene/mesh_builders.h"

namespace candela::test {

// Indices in makeCornellBox()'s materials and its room mesh.
constexpr uint32_t kCornellLight = 3;
constexpr uint32_t kCornellFloorTriangles = 2;  // the room's first quad

// The Cornell box with a light of albedo zero (Kd 0), radiance (17, 12, 4), as many scene files have it.
inline Scene blackLightCornellBox() {
  Scene scene = makeCornellBox();
  scene.name = "black-light-cornell-box";
  scene.materials[kCornellLight].baseColor = {0, 0, 0};
  return scene;
}

// Appends the quad (a, b, c, d) with uv (0, 0), (1, 0), (1, 1), (0, 1) at its corners and normals towards `towards`.
inline void appendTexturedQuad(Mesh& mesh, Vec3 a, Vec3 b, Vec3 c, Vec3 d, Vec3 towards, uint32_t material) {
  const uint32_t first = uint32_t(mesh.positions.size());
  appendQuad(mesh, a, b, c, d, towards, material);
  const Vec2 uv[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  mesh.uvs.resize(mesh.positions.size());
  for (uint32_t i = first; i < mesh.positions.size(); ++i) {
    const Vec3 p = mesh.positions[i];
    const Vec3 corners[4] = {a, b, c, d};
    for (int k = 0; k < 4; ++k)
      if (length(p - corners[k]) == 0.0f) mesh.uvs[i] = uv[k];
  }
}

// A mesh of its own in the scene, placed as it is.
inline void addMesh(Scene& scene, Mesh mesh) {
  scene.meshes.push_back(std::move(mesh));
  scene.instances.push_back({uint32_t(scene.meshes.size() - 1), Affine3x4{}});
}

// The Cornell box with an 8 mm square emitter of radiance 2000 (grey albedo) hanging in the middle, facing the
// camera: about one pixel of a 64x64 image, a hundred times brighter than the ceiling light, which it outshines as
// a light source only a little (0.4 W against 0.55 W). (At 15 mm, 1.4 W, the room lit mostly by the one tiny light,
// the a-trous filter's 4-sample relMSE was 3.8x below raw, short of the tests' 4x: docs/denoising.md.)
inline Scene tinyBrightEmitterCornellBox() {
  Scene scene = makeCornellBox();
  scene.name = "tiny-bright-emitter";
  Material m;
  m.baseColor = {0.5f, 0.5f, 0.5f};
  m.emission = {2000, 2000, 2000};
  scene.materials.push_back(m);
  Mesh quad;
  const float h = 0.004f, x = 0.278f, y = 0.30f, z = 0.20f;
  appendQuad(quad, {x - h, y - h, z}, {x + h, y - h, z}, {x + h, y + h, z}, {x - h, y + h, z}, {0, 0, -1},
             uint32_t(scene.materials.size() - 1));
  addMesh(scene, std::move(quad));
  return scene;
}

// The Cornell box with a glowing 4x4 checkerboard (an sRGB emission texture of white and dark blue squares,
// emission 3) on the back wall, its albedo 0.5.
inline Scene emissiveTextureCornellBox() {
  Scene scene = makeCornellBox();
  scene.name = "emissive-texture";
  Texture checker;
  checker.name = "checkerboard";
  checker.width = checker.height = 4;
  checker.channels = 4;
  checker.srgb = true;
  checker.wrapU = checker.wrapV = TextureWrap::Clamp;
  for (uint32_t y = 0; y < 4; ++y)
    for (uint32_t x = 0; x < 4; ++x) {
      const bool white = (x + y) % 2 == 0;
      const uint8_t texel[4] = {uint8_t(white ? 255 : 20), uint8_t(white ? 255 : 40), 255, 255};
      checker.bytes.insert(checker.bytes.end(), texel, texel + 4);
    }
  scene.textures.push_back(std::move(checker));
  Material m;
  m.baseColor = {0.5f, 0.5f, 0.5f};
  m.emission = {3, 3, 3};
  m.emissionTexture = int32_t(scene.textures.size() - 1);
  scene.materials.push_back(m);
  Mesh panel;
  const float z = 0.5585f;
  appendTexturedQuad(panel, {0.40f, 0.18f, z}, {0.16f, 0.18f, z}, {0.16f, 0.42f, z}, {0.40f, 0.42f, z}, {0, 0, -1},
                     uint32_t(scene.materials.size() - 1));
  addMesh(scene, std::move(panel));
  return scene;
}

// A grey ground, a diffuse and a polished metal sphere under an HDR sky map: a blue gradient of radiance about 0.5
// and a sun of radiance 20000 a few texels across, 35 degrees above the horizon, in view of the camera. The sun
// makes a glint on the metal sphere and sharp shadows.
inline Scene sunAndSky() {
  Scene scene;
  scene.name = "sun-and-sky";
  Material ground;
  ground.baseColor = {0.5f, 0.5f, 0.5f};
  Material clay;
  clay.baseColor = {0.8f, 0.4f, 0.3f};
  Material metal;
  metal.type = MaterialType::Disney;
  metal.baseColor = {0.95f, 0.93f, 0.88f};
  metal.metallic = 1.0f;
  metal.roughness = 0.15f;
  scene.materials = {ground, clay, metal};
  Mesh plane;
  appendQuad(plane, {-50, 0, -50}, {50, 0, -50}, {50, 0, 50}, {-50, 0, 50}, {0, 1, 0}, 0);
  addMesh(scene, std::move(plane));
  auto addSphere = [&](Vec3 centre, float radius, uint32_t material) {
    scene.meshes.push_back(makeUvSphere(1.0f, 48, 24, material, false));
    Affine3x4 t;
    t.m[0] = t.m[5] = t.m[10] = radius;
    t.m[3] = centre.x;
    t.m[7] = centre.y;
    t.m[11] = centre.z;
    scene.instances.push_back({uint32_t(scene.meshes.size() - 1), t});
  };
  addSphere({0.9f, 0.8f, 0.0f}, 0.8f, 1);
  addSphere({-0.9f, 0.8f, 0.3f}, 0.8f, 2);

  Texture& map = scene.environment.map;
  map.name = "sky with sun";
  map.width = 128;
  map.height = 64;
  map.channels = 3;
  map.floats.resize(size_t(map.width) * map.height * 3);
  const uint32_t sunRow = 20, sunColumn = 70;  // theta = 55 degrees from the zenith, a little right of -Z
  for (uint32_t y = 0; y < map.height; ++y)
    for (uint32_t x = 0; x < map.width; ++x) {
      const float up = 1.0f - float(y) / float(map.height);  // 1 at the zenith, 0 at the nadir
      Vec3 c = Vec3{0.25f, 0.35f, 0.6f} * (0.4f + up);
      const int dx = int(x) - int(sunColumn), dy = int(y) - int(sunRow);
      if (dx * dx + dy * dy <= 1) c = {20000.0f, 19000.0f, 16000.0f};
      float* t = &map.floats[(size_t(y) * map.width + x) * 3];
      t[0] = c.x;
      t[1] = c.y;
      t[2] = c.z;
    }
  scene.camera.eye = {0.0f, 1.6f, -6.0f};
  scene.camera.target = {0.0f, 1.4f, 0.0f};
  scene.camera.verticalFovDegrees = 40.0f;
  return scene;
}

// The Cornell box with a polished floor (Blinn-Phong, a dark diffuse base under a strong specular lobe) in which
// the light and the walls are mirrored, blurred.
inline Scene glossyFloorCornellBox() {
  Scene scene = makeCornellBox();
  scene.name = "glossy-floor";
  Material floor;
  floor.type = MaterialType::BlinnPhong;
  floor.baseColor = {0.15f, 0.15f, 0.15f};
  floor.specularColor = {0.6f, 0.6f, 0.6f};
  floor.shininess = 400.0f;
  scene.materials.push_back(floor);
  for (uint32_t t = 0; t < kCornellFloorTriangles; ++t)
    scene.meshes[0].triangleMaterials[t] = uint32_t(scene.materials.size() - 1);
  return scene;
}

}  // namespace candela::test
