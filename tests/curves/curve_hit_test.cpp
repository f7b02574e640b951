// Rays against known curves on the CPU backend's Embree geometry, and the surface the kernel makes of each hit:
// position, u along the curve, v across it (pbrt-v4's convention, candela's v), normal and tangent.
#include <gtest/gtest.h>

#include <cmath>

#include "backends/cpu/embree_scene.h"
#include "backends/cpu/embree_tracer.h"
#include "curves/curve_scenes.h"
#include "kernel/bsdf/hair.h"
#include "kernel/interaction.h"
#include "scene/flat_scene.h"

namespace candela::test {
namespace {

// One mesh (or more) under the given instance transforms, traced with Embree.
struct TracedScene {
  FlatScene flat;
  SceneView view;
  EmbreeScene embree;

  explicit TracedScene(const Scene& scene) : flat(FlatScene::build(scene)), view(flat.hostView()) {
    embree.build(flat);
  }
  bool intersect(const Ray& ray, Hit& hit) const {
    return EmbreeTracer(embree.topLevel(), view).intersect(ray, hit, 0);
  }
  bool occluded(const Ray& ray) const { return EmbreeTracer(embree.topLevel(), view).occluded(ray, 0); }
};

Scene sceneOf(Mesh mesh, Affine3x4 toWorld = {}) {
  Scene scene;
  scene.name = "curve";
  scene.materials.push_back(Material{});
  scene.meshes.push_back(std::move(mesh));
  scene.instances.push_back({0, toWorld, {}});
  return scene;
}

void expectNear(Vec3 a, Vec3 b, float tolerance, const char* what) {
  EXPECT_NEAR(a.x, b.x, tolerance) << what;
  EXPECT_NEAR(a.y, b.y, tolerance) << what;
  EXPECT_NEAR(a.z, b.z, tolerance) << what;
}

// The curve (-1, 0, 0) to (1, 0, 0), radius 0.1; a ray along +z at x = 0.25, y = 0.05: half a radius across,
// on the side of cross(ray direction, dp/du) = +y, where pbrt's v is 0.75 and h = 0.5.
const Ray kRay{{0.25f, 0.05f, -5.0f}, {0, 0, 1}, 0.0f, kInf};

TEST(CurveHit, RoundCurveIsATube) {
  TracedScene traced(sceneOf(straightCurve(CurveType::Cylinder, 1.0f, 0.1f)));
  Hit hit;
  ASSERT_TRUE(traced.intersect(kRay, hit));
  const float z = -std::sqrt(0.01f - 0.0025f);  // where the ray meets the tube's near wall
  EXPECT_NEAR(hit.t, 5.0f + z, 1e-4f);
  EXPECT_NEAR(hit.b1, 0.625f, 1e-4f) << "u runs from 0 at the first control point to 1 at the last";
  const SurfaceInteraction si = makeInteraction(traced.view, hit, kRay);
  expectNear(si.position, {0.25f, 0.05f, z}, 1e-4f, "position");
  expectNear(si.geometricNormal, Vec3{0.0f, 0.05f, z} / 0.1f, 1e-3f, "the tube's outward normal");
  expectNear(si.shadingNormal, si.geometricNormal, 0.0f, "shading normal");
  expectNear(normalize(si.tangent), {1, 0, 0}, 1e-5f, "tangent along the curve");
  EXPECT_NEAR(length(si.tangent), 2.0f, 1e-4f) << "dp/du of a curve 2 long";
  EXPECT_NEAR(si.uv.x, 0.625f, 1e-4f);
  EXPECT_NEAR(si.uv.y, 0.25f, 1e-3f) << "candela's v is 1 - pbrt's 0.75";
  EXPECT_EQ(si.materialId, 0u);
  // The hair model reads pbrt's h = -1 + 2 v_pbrt back.
  EXPECT_NEAR(HairBsdf::fromMaterial(Material{}, 1.0f, si.uv).h, 0.5f, 2e-3f);

  // Just past the radius: no hit.
  EXPECT_FALSE(traced.intersect({{0.25f, 0.101f, -5.0f}, {0, 0, 1}, 0.0f, kInf}, hit));
  // The other side of the curve: h and v mirror.
  const Ray mirrored{{0.25f, -0.05f, -5.0f}, {0, 0, 1}, 0.0f, kInf};
  ASSERT_TRUE(traced.intersect(mirrored, hit));
  EXPECT_NEAR(makeInteraction(traced.view, hit, mirrored).uv.y, 0.75f, 1e-3f);
}

// A tube is one-sided: a ray that starts inside it (as a ray that crosses a hair fibre's wall does) leaves it.
TEST(CurveHit, RaysLeaveATubeFromInside) {
  TracedScene traced(sceneOf(straightCurve(CurveType::Cylinder, 1.0f, 0.1f)));
  Hit hit;
  const Ray out{{0.0f, 0.0f, 0.0f}, {0, 1, 0}, 0.0f, kInf};
  EXPECT_FALSE(traced.intersect(out, hit));
  EXPECT_FALSE(traced.occluded(out));
  // From outside, the same tube blocks.
  EXPECT_TRUE(traced.occluded({{0.0f, -1.0f, 0.0f}, {0, 1, 0}, 0.0f, kInf}));
}

TEST(CurveHit, FlatCurveFacesTheRay) {
  TracedScene traced(sceneOf(straightCurve(CurveType::Flat, 1.0f, 0.1f)));
  Hit hit;
  ASSERT_TRUE(traced.intersect(kRay, hit));
  EXPECT_NEAR(hit.t, 5.0f, 1e-3f) << "the band through the curve, facing the ray";
  EXPECT_NEAR(hit.b1, 0.625f, 1e-3f);
  const SurfaceInteraction si = makeInteraction(traced.view, hit, kRay);
  expectNear(si.position, {0.25f, 0.05f, 0.0f}, 1e-3f, "position");
  expectNear(si.geometricNormal, {0, 0, -1}, 1e-5f, "normal towards the ray's origin");
  EXPECT_NEAR(si.uv.y, 0.25f, 1e-2f);
  // A ray leaving the curve does not meet it again within its width.
  const Ray back{si.position, normalize(Vec3{0.0f, -1.0f, 0.3f}), 0.0f, kInf};
  EXPECT_FALSE(traced.occluded(back));
}

TEST(CurveHit, RibbonFollowsItsNormals) {
  TracedScene traced(sceneOf(straightCurve(CurveType::Ribbon, 1.0f, 0.1f)));
  Hit hit;
  ASSERT_TRUE(traced.intersect(kRay, hit));
  EXPECT_NEAR(hit.t, 5.0f, 1e-3f);
  const SurfaceInteraction si = makeInteraction(traced.view, hit, kRay);
  expectNear(si.geometricNormal, {0, 0, -1}, 1e-4f, "the ribbon's normal");
  EXPECT_NEAR(si.uv.y, 0.25f, 1e-2f);
  // Seen edge on, a ribbon in the plane z = 0 is not there.
  EXPECT_FALSE(traced.intersect({{0.25f, -5.0f, 0.05f}, {0, 1, 0}, 0.0f, kInf}, hit));
}

// Under an instance transform (scaled by 2, moved by (1, 2, 3)) the surface is in world space.
TEST(CurveHit, InstanceTransform) {
  Affine3x4 toWorld;
  toWorld.m[0] = toWorld.m[5] = toWorld.m[10] = 2.0f;
  toWorld.m[3] = 1.0f;
  toWorld.m[7] = 2.0f;
  toWorld.m[11] = 3.0f;
  TracedScene traced(sceneOf(straightCurve(CurveType::Cylinder, 1.0f, 0.1f), toWorld));
  const Ray ray{{1.5f, 2.1f, -5.0f}, {0, 0, 1}, 0.0f, kInf};  // the world image of kRay
  Hit hit;
  ASSERT_TRUE(traced.intersect(ray, hit));
  const float z = 3.0f - 2.0f * std::sqrt(0.0075f);
  EXPECT_NEAR(hit.t, 5.0f + z, 1e-3f);
  const SurfaceInteraction si = makeInteraction(traced.view, hit, ray);
  expectNear(si.position, {1.5f, 2.1f, z}, 1e-3f, "position");
  expectNear(si.geometricNormal, Vec3{0.0f, 0.05f, -std::sqrt(0.0075f)} / 0.1f, 1e-3f, "normal");
  EXPECT_NEAR(length(si.tangent), 4.0f, 1e-3f);
  EXPECT_NEAR(si.uv.y, 0.25f, 1e-3f);
}

}  // namespace
}  // namespace candela::test
