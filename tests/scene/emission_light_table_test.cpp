// Emissive triangles are weighed for light sampling by what their emission texture shows over them, and those
// that emit nothing there stay out of the light table.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "kernel/lights.h"
#include "render/render_support.h"
#include "scene/emission_average.h"
#include "scene/flat_scene.h"

namespace candela {
namespace {

// 16 x 16 linear texels, white where u < 0.5, black elsewhere, clamped at the edges.
Texture halfWhiteTexture() {
  Texture t;
  t.name = "half white";
  t.width = t.height = 16;
  t.channels = 3;
  t.wrapU = t.wrapV = TextureWrap::Clamp;  // no light from the far edge at u = 0
  t.floats.resize(16 * 16 * 3);
  for (uint32_t y = 0; y < 16; ++y)
    for (uint32_t x = 0; x < 16; ++x)
      for (uint32_t c = 0; c < 3; ++c) t.floats[(y * 16 + x) * 3 + c] = x < 8 ? 1.0f : 0.0f;
  return t;
}

// Appends a unit square at height y facing down, with texture coordinates spanning uvLo .. uvHi.
void addDownFacingQuad(Mesh& mesh, float x0, float y, Vec2 uvLo, Vec2 uvHi, uint32_t materialId) {
  uint32_t first = uint32_t(mesh.positions.size());
  mesh.positions.insert(mesh.positions.end(), {{x0, y, 0}, {x0 + 1, y, 0}, {x0 + 1, y, 1}, {x0, y, 1}});
  mesh.uvs.insert(mesh.uvs.end(), {{uvLo.x, uvLo.y}, {uvHi.x, uvLo.y}, {uvHi.x, uvHi.y}, {uvLo.x, uvHi.y}});
  // Wound so that the geometric normal points down (-y).
  mesh.indices.insert(mesh.indices.end(), {first, first + 1, first + 2, first, first + 2, first + 3});
  mesh.triangleMaterials.insert(mesh.triangleMaterials.end(), {materialId, materialId});
}

// Three emitting squares under one textured material: one whose coordinates lie in the white half, one in the
// black half, one spanning the whole texture.
Scene texturedEmitters() {
  Scene scene;
  Material light;
  light.emission = {2, 2, 2};
  light.emissionTexture = 0;
  scene.materials = {light};
  scene.textures = {halfWhiteTexture()};
  Mesh mesh;
  addDownFacingQuad(mesh, 0, 1, {0.05f, 0.05f}, {0.2f, 0.2f}, 0);
  addDownFacingQuad(mesh, 2, 1, {0.8f, 0.05f}, {0.95f, 0.2f}, 0);
  addDownFacingQuad(mesh, 4, 1, {0.0f, 0.0f}, {1.0f, 1.0f}, 0);
  scene.meshes = {mesh};
  scene.instances.push_back({0, Affine3x4{}});
  return scene;
}

TEST(EmissionLightTable, MeanOfATextureOverATriangle) {
  FlatScene flat = FlatScene::build(texturedEmitters());
  TexelArrays arrays = flat.hostView().texels;
  EXPECT_NEAR(meanTextureOverTriangle(arrays, 0, {0.1f, 0.1f}, {0.3f, 0.1f}, {0.1f, 0.3f}).x, 1.0f, 1e-4f);
  EXPECT_NEAR(meanTextureOverTriangle(arrays, 0, {0.7f, 0.1f}, {0.9f, 0.1f}, {0.7f, 0.3f}).x, 0.0f, 1e-4f);
  // (0,0), (1,0), (1,1): the part with u < 0.5 is a quarter of it; (0,0), (1,1), (0,1): three quarters.
  EXPECT_NEAR(meanTextureOverTriangle(arrays, 0, {0, 0}, {1, 0}, {1, 1}).x, 0.25f, 0.03f);
  EXPECT_NEAR(meanTextureOverTriangle(arrays, 0, {0, 0}, {1, 1}, {0, 1}).x, 0.75f, 0.03f);
}

TEST(EmissionLightTable, LightsAreWeighedByTheirTexturesAndDarkOnesLeftOut) {
  FlatScene flat = FlatScene::build(texturedEmitters());
  // The black square's two triangles (primitives 2 and 3) are left out.
  ASSERT_EQ(flat.lights.size(), 4u);
  std::vector<uint32_t> primitives;
  for (const LightTriangle& l : flat.lights) primitives.push_back(l.primitiveId);
  EXPECT_EQ(primitives, (std::vector<uint32_t>{0, 1, 4, 5}));
  const float fullPower = trianglePower({2, 2, 2}, 0.5f);  // area 0.5, the texture white all over it
  EXPECT_NEAR(flat.lights[0].power, fullPower, 1e-4f);
  EXPECT_NEAR(flat.lights[1].power, fullPower, 1e-4f);
  EXPECT_NEAR(flat.lights[2].power, 0.25f * fullPower, 0.03f * fullPower);
  EXPECT_NEAR(flat.lights[3].power, 0.75f * fullPower, 0.03f * fullPower);
  // The power table and the light BVH pick by these weights.
  SceneView view = flat.hostView();
  double sum = 0.0;
  for (const LightTriangle& l : flat.lights) sum += powerTablePmf(view, l);
  EXPECT_NEAR(sum, 1.0, 1e-5);
  EXPECT_NEAR(powerTablePmf(view, flat.lights[0]), flat.lights[0].power / (2.0f * fullPower + fullPower), 1e-5f);
  EXPECT_NEAR(flat.lightBvh[0].bounds.phi, 3.0f * fullPower, 0.03f * fullPower);
}

// The textured emitters over a white floor, lit by them alone, against the same light made of untextured
// triangles that emit the texture's value where they are: the images must agree, whatever the weights.
TEST(EmissionLightTable, TexturedEmittersRenderAsTheirUntexturedEquivalent) {
  Scene textured = texturedEmitters();
  Material floor;
  floor.baseColor = {0.8f, 0.8f, 0.8f};
  Mesh floorMesh;
  floorMesh.positions = {{-1, 0, -1}, {7, 0, -1}, {7, 0, 2}, {-1, 0, 2}};
  floorMesh.indices = {0, 2, 1, 0, 3, 2};
  textured.materials.push_back(floor);
  floorMesh.triangleMaterials = {1, 1};
  textured.meshes.push_back(floorMesh);
  textured.instances.push_back({1, Affine3x4{}});
  textured.camera.eye = {3, 0.5f, 4};
  textured.camera.target = {3, 0.2f, 0.5f};
  textured.camera.verticalFovDegrees = 60.0f;

  // Untextured: emission 2 where u < 0.5. The spanning square is cut along u = 0.5 into two squares of its own.
  Scene plain = textured;
  plain.textures.clear();
  Material bright, dark;
  bright.emission = {2, 2, 2};
  plain.materials = {bright, floor, dark};
  Mesh lights;
  addDownFacingQuad(lights, 0, 1, {0, 0}, {1, 1}, 0);
  addDownFacingQuad(lights, 2, 1, {0, 0}, {1, 1}, 2);
  for (uint32_t half = 0; half < 2; ++half) {
    uint32_t first = uint32_t(lights.positions.size());
    float x0 = 4.0f + 0.5f * float(half);
    lights.positions.insert(lights.positions.end(), {{x0, 1, 0}, {x0 + 0.5f, 1, 0}, {x0 + 0.5f, 1, 1}, {x0, 1, 1}});
    lights.uvs.insert(lights.uvs.end(), {{0, 0}, {1, 0}, {1, 1}, {0, 1}});
    lights.indices.insert(lights.indices.end(), {first, first + 1, first + 2, first, first + 2, first + 3});
    lights.triangleMaterials.insert(lights.triangleMaterials.end(), {half == 0 ? 0u : 2u, half == 0 ? 0u : 2u});
  }
  plain.meshes[0] = lights;

  RenderSettings settings;
  settings.width = 48;
  settings.height = 32;
  settings.maxDepth = 2;
  settings.seed = 1;
  Image a = test::renderCpu(textured, settings, 256);
  settings.seed = 2;
  Image b = test::renderCpu(plain, settings, 256);
  test::PixelStatistics sa = test::luminanceStatistics(a), sb = test::luminanceStatistics(b);
  ASSERT_GT(sa.mean, 0.01);
  // Pixel means differ by noise only: compare the difference of the image means with its standard error.
  double difference = 0.0, squares = 0.0;
  for (size_t i = 0; i < a.pixels.size(); ++i) {
    double d = luminance(a.pixels[i]) - luminance(b.pixels[i]);
    difference += d;
    squares += d * d;
  }
  double n = double(a.pixels.size()), meanDifference = difference / n;
  double standardError = std::sqrt(std::fmax(0.0, squares / n - meanDifference * meanDifference) / n);
  EXPECT_LT(std::fabs(meanDifference), 4.0 * standardError + 1e-6) << sa.mean << " vs " << sb.mean;
  std::printf("textured %.5f, untextured %.5f, difference %.2e, standard error %.2e\n", sa.mean, sb.mean,
              meanDifference, standardError);
}

}  // namespace
}  // namespace candela
