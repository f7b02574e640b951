// The light BVH: its sampling and its pmf agree, the pmfs over all lights sum to one where every light can reach
// the point (and to at most one elsewhere), no light that can reach a
// point is given probability zero, the frequencies of the picks follow the pmf, and next-event estimation's
// densities (kernel/lights.h) agree between sampling a light and hitting it, with either light sampler.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "kernel/lights.h"
#include "scene/flat_scene.h"
#include "scene/light_bvh.h"
#include "support/chi2.h"

namespace candela {
namespace {

Vec3 randomVec(std::mt19937& rng, float lo, float hi) {
  std::uniform_real_distribution<float> d(lo, hi);
  return {d(rng), d(rng), d(rng)};
}

Vec3 randomDirection(std::mt19937& rng) {
  for (;;) {
    Vec3 v = randomVec(rng, -1.0f, 1.0f);
    float l = length(v);
    if (l > 0.1f && l <= 1.0f) return v / l;
  }
}

// Small emissive triangles of random size, orientation and emission scattered through a box, under a plain and
// a mirroring instance, with some non-emissive triangles between them.
Scene randomLightScene(uint32_t triangleCount, uint32_t seed) {
  std::mt19937 rng(seed);
  Scene scene;
  Material dark;
  scene.materials.push_back(dark);
  for (int i = 0; i < 4; ++i) {
    Material lamp;
    lamp.emission = randomVec(rng, 0.1f, 5.0f);
    scene.materials.push_back(lamp);
  }
  Mesh mesh;
  std::uniform_real_distribution<float> size(0.05f, 1.0f);
  std::uniform_int_distribution<uint32_t> material(0, 4);
  for (uint32_t t = 0; t < triangleCount; ++t) {
    Vec3 c = randomVec(rng, -10.0f, 10.0f);
    float s = size(rng);
    uint32_t first = uint32_t(mesh.positions.size());
    for (int k = 0; k < 3; ++k) mesh.positions.push_back(c + randomDirection(rng) * s);
    mesh.indices.insert(mesh.indices.end(), {first, first + 1, first + 2});
    mesh.triangleMaterials.push_back(material(rng));
  }
  scene.meshes = {mesh};
  Affine3x4 mirror;
  mirror.m[0] = -1.0f;
  mirror.m[3] = 25.0f;
  scene.instances = {{0, Affine3x4{}}, {0, mirror}};
  return scene;
}

std::vector<LightSampleContext> randomContexts(uint32_t count, uint32_t seed) {
  std::mt19937 rng(seed);
  std::vector<LightSampleContext> contexts;
  for (uint32_t i = 0; i < count; ++i) {
    Vec3 p = randomVec(rng, -15.0f, 40.0f);
    // Every fourth point has no surface (a medium or the camera), as pbrt's contexts without a normal.
    Vec3 n = i % 4 == 3 ? Vec3{0, 0, 0} : randomDirection(rng);
    contexts.push_back({p, n});
  }
  return contexts;
}

class LightBvhTest : public ::testing::Test {
 protected:
  void SetUp() override {
    flat_ = FlatScene::build(randomLightScene(600, 11));
    view_ = flat_.hostView();
  }
  FlatScene flat_;
  SceneView view_;
};

TEST_F(LightBvhTest, EveryLightHasOneLeafAndTheTreeIsComplete) {
  ASSERT_GT(view_.lightCount, 500u);
  ASSERT_EQ(flat_.lightBvh.size(), 2 * flat_.lights.size() - 1);
  std::vector<int> leaves(flat_.lights.size(), 0);
  for (const LightBvhNode& node : flat_.lightBvh)
    if (node.isLeaf) ++leaves[node.childOrLight];
  for (size_t i = 0; i < leaves.size(); ++i) EXPECT_EQ(leaves[i], 1) << "light " << i;
  // The root bounds every light, with all their power.
  double phi = 0.0;
  for (const LightTriangle& light : flat_.lights) phi += triangleLightBounds(light).phi;
  EXPECT_NEAR(flat_.lightBvh[0].bounds.phi, phi, 1e-4 * phi);
}

TEST_F(LightBvhTest, SampledPmfIsThePmfOfTheSampledLight) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  for (const LightSampleContext& ctx : randomContexts(200, 5)) {
    for (int i = 0; i < 50; ++i) {
      SampledLight picked = sampleLightBvh(view_, ctx, uniform(rng));
      if (picked.pmf == 0.0f) continue;
      ASSERT_LT(picked.index, view_.lightCount);
      EXPECT_NEAR(lightBvhPmf(view_, ctx, picked.index), picked.pmf, 1e-5f * picked.pmf);
    }
  }
}

// Where every light can reach the point, sampling always picks one: the pmfs sum to one.
TEST(LightBvh, PmfsSumToOneWhereEveryLightCanReachThePoint) {
  std::mt19937 rng(12);
  Scene scene = randomLightScene(400, 13);
  // Every triangle faces up (towards +y), below every point.
  Mesh& mesh = scene.meshes[0];
  for (size_t t = 0; t < mesh.triangleCount(); ++t) {
    Vec3& p0 = mesh.positions[mesh.indices[3 * t]];
    Vec3& p1 = mesh.positions[mesh.indices[3 * t + 1]];
    Vec3& p2 = mesh.positions[mesh.indices[3 * t + 2]];
    p0.y = p1.y = p2.y = p0.y * 0.1f;
    if (cross(p1 - p0, p2 - p0).y < 0.0f) std::swap(p1, p2);
  }
  scene.instances.resize(1);
  FlatScene flat = FlatScene::build(scene);
  SceneView view = flat.hostView();
  for (LightSampleContext ctx : randomContexts(100, 14)) {
    ctx.p.y = 2.0f + fabsf(ctx.p.y);
    double sum = 0.0;
    for (uint32_t i = 0; i < view.lightCount; ++i) sum += lightBvhPmf(view, ctx, i);
    EXPECT_NEAR(sum, 1.0, 1e-4);
  }
}

// Elsewhere sampling may find, below a node some light in it could reach the point from, that none does: that
// much probability picks nothing, so the pmfs sum to at most one. No light that can reach the point is left out.
TEST_F(LightBvhTest, PmfsSumToAtMostOneAndNoReachableLightIsLeftOut) {
  for (const LightSampleContext& ctx : randomContexts(200, 6)) {
    double sum = 0.0;
    for (uint32_t i = 0; i < view_.lightCount; ++i) {
      float pmf = lightBvhPmf(view_, ctx, i);
      sum += pmf;
      // A light the point sees the front of, away from the surface's tangent plane, must be possible to pick.
      const LightTriangle& light = flat_.lights[i];
      Vec3 n = normalize(cross(light.edge1, light.edge2)) * light.frontSign;
      Vec3 centre = light.p0 + (light.edge1 + light.edge2) * (1.0f / 3.0f);
      Vec3 toPoint = normalize(ctx.p - centre);
      bool inFront = dot(n, toPoint) > 1e-3f;
      bool offTangentPlane = isBlack(ctx.n) || fabsf(dot(ctx.n, toPoint)) > 1e-3f;
      if (inFront && offTangentPlane) {
        EXPECT_GT(pmf, 0.0f) << "light " << i;
      }
    }
    EXPECT_LE(sum, 1.0 + 1e-5);
    EXPECT_GT(sum, 0.5);
  }
}

// Pearson's chi-square test of the picks' frequencies against the pmf (and of picking nothing against what the
// pmfs leave), lights expecting fewer than 5 picks pooled.
TEST_F(LightBvhTest, PickFrequenciesFollowThePmf) {
  const std::vector<LightSampleContext> contexts = randomContexts(4, 8);
  const int kSamples = 400000;
  for (const LightSampleContext& ctx : contexts) {
    // One cell per light, and the last for picking nothing.
    std::vector<double> expected(view_.lightCount + 1), observed(view_.lightCount + 1, 0.0);
    double sum = 0.0;
    for (uint32_t i = 0; i < view_.lightCount; ++i) {
      expected[i] = double(lightBvhPmf(view_, ctx, i)) * kSamples;
      sum += expected[i];
    }
    expected[view_.lightCount] = std::max(0.0, kSamples - sum);
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    for (int s = 0; s < kSamples; ++s) {
      SampledLight picked = sampleLightBvh(view_, ctx, uniform(rng));
      observed[picked.pmf > 0.0f ? picked.index : view_.lightCount] += 1.0;
    }
    double chi2 = 0.0, pooledExpected = 0.0, pooledObserved = 0.0;
    int cells = 0;
    for (uint32_t i = 0; i <= view_.lightCount; ++i) {
      if (expected[i] < 5.0) {
        pooledExpected += expected[i];
        pooledObserved += observed[i];
        continue;
      }
      chi2 += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
      ++cells;
    }
    if (pooledExpected >= 5.0) {
      chi2 += (pooledObserved - pooledExpected) * (pooledObserved - pooledExpected) / pooledExpected;
      ++cells;
    } else {
      EXPECT_LT(pooledObserved, 20.0);
    }
    ASSERT_GT(cells, 10);
    double pValue = test::upperIncompleteGammaQ(0.5 * (cells - 1), 0.5 * chi2);
    double significance = 1.0 - std::pow(1.0 - 0.01, 1.0 / double(contexts.size()));
    EXPECT_GT(pValue, significance) << "chi2 " << chi2 << " over " << cells << " cells";
  }
}

TEST_F(LightBvhTest, FindsEveryLightByItsTriangleAndNothingElse) {
  for (uint32_t i = 0; i < view_.lightCount; ++i)
    EXPECT_EQ(findLightIndex(view_, flat_.lights[i].instanceId, flat_.lights[i].primitiveId), i);
  // The non-emissive triangles of both instances, and an instance beyond the last.
  const Scene scene = randomLightScene(600, 11);
  const Mesh& mesh = scene.meshes[0];
  for (uint32_t instance = 0; instance < 2; ++instance)
    for (uint32_t t = 0; t < mesh.triangleCount(); ++t)
      if (mesh.triangleMaterials[t] == 0) {
        EXPECT_EQ(findLightIndex(view_, instance, t), view_.lightCount);
      }
  EXPECT_EQ(findLightIndex(view_, 2, 0), view_.lightCount);
}

// Next-event estimation's solid-angle density of a sampled light point must be the one the path tracer weighs
// a BSDF sample that hits the same point with, or MIS is biased; for triangles sampled by area and by solid
// angle alike.
TEST_F(LightBvhTest, LightSamplePdfIsTheDensityOfHittingThatPoint) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  for (LightSamplerKind kind : {LightSamplerKind::Bvh, LightSamplerKind::Power}) {
    int checked = 0, bySolidAngle = 0;
    for (const LightSampleContext& ctx : randomContexts(100, 7)) {
      for (int i = 0; i < 20; ++i) {
        LightSample ls = sampleLight(view_, kind, ctx, uniform(rng), {uniform(rng), uniform(rng)});
        if (!ls.valid) continue;
        const LightTriangle& light = flat_.lights[ls.lightIndex];
        Hit hit;
        hit.instanceId = light.instanceId;
        hit.primitiveId = light.primitiveId;
        Vec3 n = normalize(cross(light.edge1, light.edge2)) * light.frontSign;
        float pdf = triangleLightPdf(view_, kind, ctx, hit, ls.distance, -dot(n, ls.wi));
        EXPECT_NEAR(pdf, ls.pdf, 1e-4f * ls.pdf);
        ++checked;
        if (sphericalSamplingSolidAngle(light, ctx.p) > 0.0f) ++bySolidAngle;
      }
    }
    EXPECT_GT(checked, 1000);
    EXPECT_GT(bySolidAngle, 100);
    EXPECT_LT(bySolidAngle, checked - 100);
  }
}

// Many lights at one place (their centroids alike along every axis) leave no split by cost: the halves by count
// keep the tree, and the bit trails, shallow.
TEST(LightBvh, CoincidentLightsGiveABalancedTree) {
  std::vector<LightTriangle> lights(5000);
  for (uint32_t i = 0; i < lights.size(); ++i) {
    lights[i].p0 = {0, 0, 0};
    lights[i].edge1 = {1, 0, 0};
    lights[i].edge2 = {0, 1, 0};
    lights[i].radiance = {1, 1, 1};
    lights[i].area = 0.5f;
    lights[i].power = 0.5f;
    lights[i].primitiveId = i;
  }
  LightBvh bvh = buildLightBvh(lights);
  ASSERT_EQ(bvh.nodes.size(), 2 * lights.size() - 1);
  for (uint64_t trail : bvh.bitTrails) EXPECT_LT(trail, uint64_t(1) << 14);
}

TEST(LightBvh, NoLightsNoNodes) {
  LightBvh bvh = buildLightBvh({});
  EXPECT_TRUE(bvh.nodes.empty());
  EXPECT_TRUE(bvh.bitTrails.empty());
}

}  // namespace
}  // namespace candela
