// Mix materials choose one of their two materials per shading point (kernel/textured_material.h): the share of
// points taking each must match the amount, also where a texture gives it and through mixes of mixes.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "kernel/textured_material.h"
#include "scene/flat_scene.h"
#include "scene/mesh_builders.h"

namespace candela {
namespace {

Material grey(float albedo) {
  Material m;
  m.baseColor = {albedo, albedo, albedo};
  return m;
}

Material mix(uint32_t first, uint32_t second, float amount) {
  Material m;
  m.type = MaterialType::Mix;
  m.mixedMaterials[0] = first;
  m.mixedMaterials[1] = second;
  m.mixAmount = amount;
  return m;
}

// One unit quad (two triangles) with texture coordinates u = x, v = z, all of material `material`.
Scene quadScene(std::vector<Material> materials, uint32_t material) {
  Scene scene;
  scene.materials = std::move(materials);
  Mesh mesh;
  appendQuad(mesh, {0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}, {0, 1, 0}, material);
  for (Vec3 p : mesh.positions) mesh.uvs.push_back({p.x, p.z});
  scene.meshes.push_back(mesh);
  scene.instances.push_back({0, Affine3x4{}});
  return scene;
}

// Counts, over `n` random points of the quad whose u lies in [uMin, uMax) and random directions towards the
// viewer, which material the mix `mixId` chooses at each.
std::vector<size_t> countChoices(const Scene& scene, uint32_t mixId, size_t n, float uMin = 0.0f, float uMax = 1.0f) {
  FlatScene flat = FlatScene::build(scene);
  SceneView view = flat.hostView();
  std::mt19937 rng(1234);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  std::vector<size_t> counts(scene.materials.size());
  for (size_t i = 0; i < n; ++i) {
    SurfaceInteraction si;
    si.uv = {uMin + (uMax - uMin) * uniform(rng), uniform(rng)};
    si.position = {si.uv.x, 0.0f, si.uv.y};
    si.materialId = mixId;
    Vec3 wo = normalize(Vec3{uniform(rng) - 0.5f, uniform(rng), uniform(rng) - 0.5f});
    ++counts[chooseMixedMaterial(view, mixId, si, wo)];
  }
  return counts;
}

// |k - n p| within 4.5 binomial standard deviations: a false failure has probability below 1e-5.
void expectBinomialShare(size_t k, size_t n, double p) {
  double sigma = std::sqrt(double(n) * p * (1.0 - p));
  EXPECT_LE(std::fabs(double(k) - double(n) * p), 4.5 * sigma + 1e-9) << k << " of " << n << ", expected share " << p;
}

TEST(MixMaterial, TheShareOfPointsTakingTheSecondMaterialIsTheAmount) {
  const size_t n = 20000;
  for (float amount : {0.0f, 0.1f, 0.3f, 0.5f, 0.9f, 1.0f}) {
    SCOPED_TRACE("amount " + std::to_string(amount));
    std::vector<size_t> counts = countChoices(quadScene({grey(0.2f), grey(0.8f), mix(0, 1, amount)}, 2), 2, n);
    EXPECT_EQ(counts[0] + counts[1], n);  // never the mix itself
    expectBinomialShare(counts[1], n, amount);
  }
}

// The choice is per point, not per triangle: on each of the two triangles alone the share is the amount.
TEST(MixMaterial, EachTriangleShowsBothMaterials) {
  Scene scene = quadScene({grey(0.2f), grey(0.8f), mix(0, 1, 0.3f)}, 2);
  FlatScene flat = FlatScene::build(scene);
  SceneView view = flat.hostView();
  for (uint32_t triangle : {0u, 1u}) {
    size_t second = 0, n = 4000;
    for (size_t i = 0; i < n; ++i) {
      Hit hit;
      hit.primitiveId = triangle;
      hit.b1 = float(i % 61) / 128.0f;
      hit.b2 = float(i / 61) / 128.0f;
      SurfaceInteraction si = makeInteraction(view, hit, Ray{});
      second += chooseMixedMaterial(view, si.materialId, si, {0, 1, 0}) == 1;
    }
    expectBinomialShare(second, n, 0.3);
  }
}

TEST(MixMaterial, ATexturedAmountIsTheFactorTimesTheTexel) {
  Scene scene = quadScene({grey(0.2f), grey(0.8f), mix(0, 1, 0.5f)}, 2);
  Texture amount;  // 0.2 on the left half of the quad, 1 on the right, linear
  amount.width = 64;
  amount.height = 1;
  amount.channels = 1;
  for (uint32_t x = 0; x < amount.width; ++x) amount.bytes.push_back(x < 32 ? 51 : 255);
  scene.textures.push_back(amount);
  scene.materials[2].mixAmountTexture = 0;
  const size_t n = 20000;
  // Away from the edges, where the bilinear lookup blends the halves (and wraps around).
  std::vector<size_t> left = countChoices(scene, 2, n, 0.1f, 0.4f), right = countChoices(scene, 2, n, 0.6f, 0.9f);
  expectBinomialShare(left[1], n, 0.5 * 0.2);
  expectBinomialShare(right[1], n, 0.5 * 1.0);
}

// A mix of a mix and a third material: the inner and outer choices are independent (one number for both would
// never take the inner mix's second material where the outer takes the inner mix).
TEST(MixMaterial, NestedMixesChooseIndependently) {
  const size_t n = 20000;
  std::vector<size_t> counts =
      countChoices(quadScene({grey(0.1f), grey(0.5f), grey(0.9f), mix(0, 1, 0.5f), mix(3, 2, 0.5f)}, 4), 4, n);
  expectBinomialShare(counts[0], n, 0.25);
  expectBinomialShare(counts[1], n, 0.25);
  expectBinomialShare(counts[2], n, 0.5);
}

// One vertex, one material: every evaluation at the same point and direction chooses alike (next-event
// estimation, BSDF sampling and MIS see one BSDF), and the surface's emission is the mix's own.
TEST(MixMaterial, AVertexAlwaysChoosesAlikeAndEmitsAsTheMix) {
  Scene scene = quadScene({grey(0.2f), grey(0.8f), mix(0, 1, 0.5f)}, 2);
  scene.materials[0].emission = {5, 5, 5};
  scene.materials[2].emission = {1, 2, 3};
  FlatScene flat = FlatScene::build(scene);
  SceneView view = flat.hostView();
  size_t differing = 0;
  for (uint32_t i = 0; i < 100; ++i) {
    Hit hit;
    hit.b1 = float(i) / 256.0f;
    hit.b2 = 0.25f;
    SurfaceInteraction si = makeInteraction(view, hit, Ray{});
    Vec3 wo = normalize(Vec3{0.1f * float(i % 7), 1.0f, 0.2f});
    Material first = evaluateSurfaceMaterial(view, si, wo);
    for (int repeat = 0; repeat < 3; ++repeat)
      differing += evaluateSurfaceMaterial(view, si, wo).baseColor.x != first.baseColor.x;
    EXPECT_EQ(first.emission.x, 1.0f);
    EXPECT_EQ(first.emission.z, 3.0f);
  }
  EXPECT_EQ(differing, 0u);
}

TEST(MixMaterial, ValidationRejectsMissingMaterialsCyclesAndDeepChains) {
  auto rejects = [](std::vector<Material> materials) {
    try {
      FlatScene::build(quadScene(std::move(materials), 0));
    } catch (const std::runtime_error&) {
      return true;
    }
    return false;
  };
  EXPECT_TRUE(rejects({mix(1, 2, 0.5f), grey(0.5f)}));       // a missing material
  EXPECT_TRUE(rejects({mix(1, 1, 0.5f), mix(0, 0, 0.5f)}));  // a cycle
  EXPECT_TRUE(rejects({mix(0, 0, 0.5f)}));                   // a mix of itself
  // Material 0 heads a chain of `mixes` mixes down to a grey.
  auto chainOf = [](uint32_t mixes) {
    std::vector<Material> chain;
    for (uint32_t i = 0; i < mixes; ++i) chain.push_back(mix(i + 1, i + 1, 0.5f));
    chain.push_back(grey(0.5f));
    return chain;
  };
  EXPECT_FALSE(rejects(chainOf(kMaxMixDepth)));
  EXPECT_TRUE(rejects(chainOf(kMaxMixDepth + 1)));
}

}  // namespace
}  // namespace candela
