// The light BVH, over emissive triangles alone and mixed with point and spot lights: its sampling and its pmf
// agree, the pmfs over all lights sum to one where every light can reach the point (and to at most one
// elsewhere), no light that can reach a point is given probability zero, the frequencies of the picks follow the
// pmf, and next-event estimation's densities (kernel/lights.h) agree between sampling a light and hitting it,
// with either light sampler. Then the split between the environment, directional lights and the bounded ones.
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

// `count` point and spot lights (alternately) of random intensity through the same box, the spots aimed anywhere
// with cones from narrow to wide.
void addPunctualLights(Scene& scene, uint32_t count, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> degrees(2.0f, 80.0f);
  for (uint32_t i = 0; i < count; ++i) {
    PunctualLight light;
    light.type = i % 2 == 0 ? PunctualLightType::Point : PunctualLightType::Spot;
    light.position = randomVec(rng, -10.0f, 10.0f);
    light.intensity = randomVec(rng, 0.02f, 2.0f);  // about the triangles' power, 1 to 25
    if (light.type == PunctualLightType::Spot) {
      light.direction = randomDirection(rng);
      float outer = degrees(rng), inner = outer * std::uniform_real_distribution<float>(0.0f, 1.0f)(rng);
      light.cosOuter = std::cos(outer * kPi / 180.0f);
      light.cosInner = std::cos(inner * kPi / 180.0f);
    }
    scene.punctualLights.push_back(light);
  }
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

// Whether the bounded light `index` can send light to ctx, away from the tangent plane of its surface: a
// triangle whose front faces it, a point light, a spot light within its outer cone (margins against rounding).
bool canReach(const SceneView& view, uint32_t index, const LightSampleContext& ctx) {
  Vec3 at, toPoint;
  bool facing;
  if (index < view.lightCount) {
    const LightTriangle& light = view.lights[index];
    Vec3 n = normalize(cross(light.edge1, light.edge2)) * light.frontSign;
    at = light.p0 + (light.edge1 + light.edge2) * (1.0f / 3.0f);
    toPoint = normalize(ctx.p - at);
    facing = dot(n, toPoint) > 1e-3f;
  } else {
    const PunctualLight& light = view.punctualLights[index - view.lightCount];
    at = light.position;
    toPoint = normalize(ctx.p - at);
    facing = light.type == PunctualLightType::Point || dot(light.direction, toPoint) > light.cosOuter + 1e-3f;
  }
  return facing && (isBlack(ctx.n) || fabsf(dot(ctx.n, toPoint)) > 1e-3f);
}

// Triangles alone (the parameter 0), or with that many point and spot lights among them.
class LightBvhTest : public ::testing::TestWithParam<uint32_t> {
 protected:
  void SetUp() override {
    Scene scene = randomLightScene(600, 11);
    addPunctualLights(scene, GetParam(), 15);
    flat_ = FlatScene::build(scene);
    view_ = flat_.hostView();
  }
  FlatScene flat_;
  SceneView view_;
};

INSTANTIATE_TEST_SUITE_P(TrianglesAndPunctualLights, LightBvhTest, ::testing::Values(0u, 120u));

TEST_P(LightBvhTest, EveryLightHasOneLeafAndTheTreeIsComplete) {
  ASSERT_GT(view_.lightCount, 500u);
  ASSERT_EQ(view_.boundedPunctualLightCount, GetParam());
  const uint32_t count = boundedLightCount(view_);
  ASSERT_EQ(flat_.lightBvh.size(), 2 * count - 1);
  std::vector<int> leaves(count, 0);
  for (const LightBvhNode& node : flat_.lightBvh)
    if (node.isLeaf) ++leaves[node.childOrLight];
  for (size_t i = 0; i < leaves.size(); ++i) EXPECT_EQ(leaves[i], 1) << "light " << i;
  // The root bounds every light, with all their power.
  double phi = 0.0;
  for (const LightTriangle& light : flat_.lights) phi += triangleLightBounds(light).phi;
  for (const PunctualLight& light : flat_.punctualLights) phi += punctualLightBounds(light).phi;
  EXPECT_NEAR(flat_.lightBvh[0].bounds.phi, phi, 1e-4 * phi);
}

TEST_P(LightBvhTest, SampledPmfIsThePmfOfTheSampledLight) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  for (const LightSampleContext& ctx : randomContexts(200, 5)) {
    for (int i = 0; i < 50; ++i) {
      SampledLight picked = sampleLightBvh(view_, ctx, uniform(rng));
      if (picked.pmf == 0.0f) continue;
      ASSERT_LT(picked.index, boundedLightCount(view_));
      EXPECT_NEAR(lightBvhPmf(view_, ctx, picked.index), picked.pmf, 1e-5f * picked.pmf);
    }
  }
}

// A child of a ten-thousandth of its parent's importance is picked with that probability, to the last digits, as
// lightBvhPmf() gives it (the descent once took 1 - p for it, which cancels to three digits).
TEST(LightBvh, SampledPmfOfAnUnlikelyChildIsExact) {
  Scene scene;
  for (float x : {0.1f, 10.0f}) {
    PunctualLight light;
    light.position = {x, 0, 0};
    light.intensity = {1, 1, 1};
    scene.punctualLights.push_back(light);
  }
  FlatScene flat = FlatScene::build(scene);
  SceneView view = flat.hostView();
  const LightSampleContext ctx{{0, 0, 0}, {0, 0, 0}};
  int picked[2] = {};
  for (float u : {0.0f, 0.5f, 0.99995f, 0.99999994f}) {
    SampledLight light = sampleLightBvh(view, ctx, u);
    ASSERT_GT(light.pmf, 0.0f);
    EXPECT_FLOAT_EQ(light.pmf, lightBvhPmf(view, ctx, light.index)) << "u " << u;
    ++picked[light.index];
  }
  EXPECT_GT(picked[0], 0);
  EXPECT_GT(picked[1], 0);
  EXPECT_NEAR(lightBvhPmf(view, ctx, 1), 1e-4, 1e-6);
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
  // Point lights among them, and spot lights far below aiming up, every point within their inner or outer cone.
  std::mt19937 punctualRng(15);
  for (int i = 0; i < 40; ++i) {
    PunctualLight light;
    light.intensity = randomVec(punctualRng, 0.1f, 20.0f);
    light.position = randomVec(punctualRng, -10.0f, 10.0f);
    if (i % 2 == 1) {
      light.type = PunctualLightType::Spot;
      light.position = {12.0f + light.position.x, -100.0f, 12.0f + light.position.z};
      light.direction = {0, 1, 0};
      light.cosOuter = std::cos(60.0f * kPi / 180.0f);
      light.cosInner = std::cos(float(i) * 0.5f * kPi / 180.0f);
    } else {
      light.position.y = -1.0f;
    }
    scene.punctualLights.push_back(light);
  }
  FlatScene flat = FlatScene::build(scene);
  SceneView view = flat.hostView();
  ASSERT_EQ(view.boundedPunctualLightCount, 40u);
  for (LightSampleContext ctx : randomContexts(100, 14)) {
    ctx.p.y = 2.0f + fabsf(ctx.p.y);
    double sum = 0.0;
    for (uint32_t i = 0; i < boundedLightCount(view); ++i) sum += lightBvhPmf(view, ctx, i);
    EXPECT_NEAR(sum, 1.0, 1e-4);
  }
}

// Elsewhere sampling may find, below a node some light in it could reach the point from, that none does: that
// much probability picks nothing, so the pmfs sum to at most one. No light that can reach the point is left out.
TEST_P(LightBvhTest, PmfsSumToAtMostOneAndNoReachableLightIsLeftOut) {
  for (const LightSampleContext& ctx : randomContexts(200, 6)) {
    double sum = 0.0;
    for (uint32_t i = 0; i < boundedLightCount(view_); ++i) {
      float pmf = lightBvhPmf(view_, ctx, i);
      sum += pmf;
      if (canReach(view_, i, ctx)) {
        EXPECT_GT(pmf, 0.0f) << "light " << i;
      }
    }
    EXPECT_LE(sum, 1.0 + 1e-5);
    EXPECT_GT(sum, 0.5);
  }
}

// A region of shading points (a context with a radius and a cone of normals, as ReSTIR's presampling gives a screen
// tile): every light that can reach some point of it keeps a positive pmf, so that a candidate drawn for the region
// can be any light that reaches any of its pixels. The region's centre alone (radius 0, its axis as the normal)
// leaves some of them out, so the test can fail.
TEST_P(LightBvhTest, RegionContextsLeaveOutNoLightThatReachesAPointOfTheRegion) {
  std::mt19937 rng(21);
  std::uniform_real_distribution<float> radii(0.2f, 4.0f), spreads(0.0f, 1.4f), uniform(0.0f, 1.0f);
  uint32_t reachable = 0, missedByTheCentre = 0;
  int r = 0;
  for (const LightSampleContext& at : randomContexts(60, 22)) {
    LightSampleContext region{at.p, {0, 0, 0}, radii(rng)};
    float spread = 0.0f;
    if (r++ % 2 == 1) {  // every other region with a cone of normals
      spread = spreads(rng);
      region.n = randomDirection(rng);
      region.cosNormalSpread = std::cos(spread);
      region.sinNormalSpread = std::sin(spread);
    }
    const LightSampleContext centre{region.p, region.n};
    for (int k = 0; k < 20; ++k) {
      LightSampleContext point{region.p + randomDirection(rng) * (region.radius * float(k) / 20.0f), {0, 0, 0}};
      if (!isBlack(region.n)) {
        // A normal within the cone: the axis turned towards a random direction by up to the spread.
        const Vec3 side = normalize(cross(region.n, randomDirection(rng)));
        const float angle = spread * uniform(rng);
        point.n = region.n * std::cos(angle) + side * std::sin(angle);
      }
      for (uint32_t i = 0; i < boundedLightCount(view_); ++i) {
        if (!canReach(view_, i, point)) continue;
        ++reachable;
        EXPECT_GT(lightBvhPmf(view_, region, i), 0.0f) << "light " << i;
        if (lightBvhPmf(view_, centre, i) == 0.0f) ++missedByTheCentre;
      }
    }
  }
  EXPECT_GT(reachable, 10000u);
  EXPECT_GT(missedByTheCentre, 100u);
}

// Pearson's chi-square test of the picks' frequencies against the pmf (and of picking nothing against what the
// pmfs leave), lights expecting fewer than 5 picks pooled.
TEST_P(LightBvhTest, PickFrequenciesFollowThePmf) {
  const std::vector<LightSampleContext> contexts = randomContexts(4, 8);
  const int kSamples = 400000;
  const uint32_t count = boundedLightCount(view_);
  for (const LightSampleContext& ctx : contexts) {
    // One cell per light, and the last for picking nothing.
    std::vector<double> expected(count + 1), observed(count + 1, 0.0);
    double sum = 0.0;
    for (uint32_t i = 0; i < count; ++i) {
      expected[i] = double(lightBvhPmf(view_, ctx, i)) * kSamples;
      sum += expected[i];
    }
    expected[count] = std::max(0.0, kSamples - sum);
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    for (int s = 0; s < kSamples; ++s) {
      SampledLight picked = sampleLightBvh(view_, ctx, uniform(rng));
      observed[picked.pmf > 0.0f ? picked.index : count] += 1.0;
    }
    const test::DiscreteChi2 chi2 = test::chi2Discrete(observed, expected);
    if (chi2.pooledExpected < 5.0) {
      EXPECT_LT(chi2.pooledObserved, 20.0);
    }
    ASSERT_GT(chi2.cells, 10);
    double significance = 1.0 - std::pow(1.0 - 0.01, 1.0 / double(contexts.size()));
    EXPECT_GT(chi2.pValue, significance) << "chi2 " << chi2.statistic << " over " << chi2.cells << " cells";
  }
}

TEST_P(LightBvhTest, FindsEveryLightByItsTriangleAndNothingElse) {
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
// A punctual light's sample carries the probability of its pick: the BVH's pmf, or its share of the power.
TEST_P(LightBvhTest, LightSamplePdfIsTheDensityOfHittingThatPoint) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  for (LightSamplerKind kind : {LightSamplerKind::Bvh, LightSamplerKind::Power}) {
    int checked = 0, bySolidAngle = 0, punctual = 0;
    // Random points see most triangles too small for solid-angle sampling; points just in front of lights see
    // them large.
    std::vector<LightSampleContext> contexts = randomContexts(100, 7);
    for (uint32_t i = 0; i < 100 && view_.lightCount > 0; ++i) {
      const LightTriangle& light = flat_.lights[(i * 7919u) % view_.lightCount];
      Vec3 n = normalize(cross(light.edge1, light.edge2)) * light.frontSign;
      float size = sqrtf(light.area);
      Vec3 centroid = light.p0 + (light.edge1 + light.edge2) * (1.0f / 3.0f);
      contexts.push_back({centroid + n * (size * (0.05f + 2.0f * uniform(rng))), i % 4 == 3 ? Vec3{} : -n});
    }
    for (size_t c = 0; c < contexts.size(); ++c) {
      const LightSampleContext& ctx = contexts[c];
      // The power table picks the light in front of a near point among all the others: more samples there.
      for (int i = 0; i < (c < 100 ? 40 : 2000); ++i) {
        LightSample ls = sampleLight(view_, kind, ctx, uniform(rng), {uniform(rng), uniform(rng)});
        if (!ls.valid) continue;
        if (ls.isDelta) {
          ASSERT_GE(ls.lightIndex, view_.lightCount);
          const PunctualLight& light = view_.punctualLights[ls.lightIndex - view_.lightCount];
          float pmf = kind == LightSamplerKind::Bvh ? lightBvhPmf(view_, ctx, ls.lightIndex)
                                                    : punctualLightPower(light) * view_.inverseLightPower;
          EXPECT_NEAR(ls.pdf, pmf, 1e-5f * pmf);
          ++punctual;
          continue;
        }
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
    if (GetParam() > 0) {
      EXPECT_GT(punctual, 50);
    } else {
      EXPECT_EQ(punctual, 0);
    }
  }
}

// The power table's frequencies over triangles and punctual lights together are their shares of the power.
TEST_P(LightBvhTest, PowerTablePicksByPower) {
  const uint32_t count = boundedLightCount(view_);
  double total = 0.0;
  std::vector<double> power(count);
  for (uint32_t i = 0; i < count; ++i) {
    power[i] = i < view_.lightCount ? trianglePower(flat_.lights[i].radiance, flat_.lights[i].area)
                                    : punctualLightPower(flat_.punctualLights[i - view_.lightCount]);
    total += power[i];
  }
  // Stratified selections: each light is picked in proportion to its power, to within one stratum.
  const int kStrata = 1 << 20;
  std::vector<int> picks(count, 0);
  for (int k = 0; k < kStrata; ++k) {
    LightSample ls =
        sampleLight(view_, LightSamplerKind::Power, {{0, 0, 0}, {0, 0, 0}}, (float(k) + 0.5f) / kStrata, {0.5f, 0.5f});
    ++picks[ls.lightIndex];  // named even where the point on a triangle faces away
  }
  for (uint32_t i = 0; i < count; ++i) EXPECT_NEAR(picks[i], power[i] / total * kStrata, 2.0) << "light " << i;
}

// Each infinite light (the environment, each directional light) is picked as often as the bounded lights
// together, as pbrt-v4's BVHLightSampler does; without bounded lights the infinite ones share everything.
TEST(LightSelection, InfiniteLightsAndTheBoundedOnesShareAlike) {
  Scene scene = randomLightScene(50, 21);
  addPunctualLights(scene, 10, 22);
  scene.environment.radiance = {0.5f, 0.5f, 0.5f};
  for (float x : {0.6f, -0.6f}) {
    PunctualLight sun;
    sun.type = PunctualLightType::Directional;
    sun.direction = normalize(Vec3{x, -1.0f, 0.2f});
    sun.intensity = {3, 3, 3};
    scene.punctualLights.insert(scene.punctualLights.begin() + 3, sun);
  }
  FlatScene flat = FlatScene::build(scene);
  SceneView view = flat.hostView();
  ASSERT_EQ(view.punctualLightCount, 12u);
  ASSERT_EQ(view.boundedPunctualLightCount, 10u);
  EXPECT_FLOAT_EQ(view.environmentSelectProbability, 0.25f);
  EXPECT_FLOAT_EQ(view.directionalSelectProbability, 0.25f);
  EXPECT_FLOAT_EQ(view.boundedSelectProbability, 0.25f);
  // Stratified selections from a point that every kind reaches.
  const int kStrata = 4000;
  int environment = 0, bounded = 0, directional[2] = {};
  for (int k = 0; k < kStrata; ++k) {
    LightSample ls =
        sampleLight(view, LightSamplerKind::Bvh, {{0, 30, 0}, {0, 0, 0}}, (float(k) + 0.5f) / kStrata, {0.3f, 0.7f});
    if (ls.isDelta && ls.lightIndex >= view.lightCount + view.boundedPunctualLightCount) {
      EXPECT_FLOAT_EQ(ls.pdf, 0.25f);
      EXPECT_GE(ls.distance, kInf);
      ++directional[ls.lightIndex - view.lightCount - view.boundedPunctualLightCount];
    } else if (!ls.isDelta && ls.distance >= kInf && ls.pdf > 0.0f) {
      ++environment;
    } else {
      ++bounded;  // or the BVH found no light in the node it chose
    }
  }
  EXPECT_EQ(environment, kStrata / 4);
  EXPECT_EQ(directional[0], kStrata / 4);
  EXPECT_EQ(directional[1], kStrata / 4);
  EXPECT_EQ(bounded, kStrata / 4);

  // Directional lights alone: they share all of it.
  Scene suns;
  suns.punctualLights.assign(scene.punctualLights.begin() + 3, scene.punctualLights.begin() + 5);
  FlatScene onlySuns = FlatScene::build(suns);
  EXPECT_FLOAT_EQ(onlySuns.directionalSelectProbability, 0.5f);
  EXPECT_EQ(onlySuns.boundedSelectProbability, 0.0f);
  EXPECT_EQ(onlySuns.environmentSelectProbability, 0.0f);
  SceneView sunView = onlySuns.hostView();
  for (float u : {0.0f, 0.49f, 0.51f, 0.99999994f}) {
    LightSample ls = sampleLight(sunView, LightSamplerKind::Bvh, {{0, 0, 0}, {0, 1, 0}}, u, {0.5f, 0.5f});
    EXPECT_TRUE(ls.valid && ls.isDelta) << u;
    EXPECT_EQ(ls.lightIndex, u < 0.5f ? 0u : 1u);
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
