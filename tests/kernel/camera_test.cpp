#include <gtest/gtest.h>

#include "kernel/camera.h"
#include "scene/scene.h"

namespace candela {
namespace {

float angleBetween(Vec3 a, Vec3 b) { return acosf(clampf(dot(normalize(a), normalize(b)), -1.0f, 1.0f)); }

TEST(Camera, CentreRayLooksAtTheTarget) {
  Camera c = Camera::lookAt({1, 2, 3}, {1, 2, 10}, {0, 1, 0}, 40.0f, 1.5f);
  Ray r = c.generateRay(150.0f, 50.0f, 300, 100);
  EXPECT_NEAR(r.direction.x, 0.0f, 1e-6f);
  EXPECT_NEAR(r.direction.y, 0.0f, 1e-6f);
  EXPECT_NEAR(r.direction.z, 1.0f, 1e-6f);
  EXPECT_EQ(r.origin.y, 2.0f);
  EXPECT_NEAR(length(r.direction), 1.0f, 1e-6f);
}

TEST(Camera, EdgesSpanTheFieldOfView) {
  const float fov = 40.0f, aspect = 2.0f;
  Camera c = Camera::lookAt({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, fov, aspect);
  Vec3 forward{0, 0, -1};
  Ray top = c.generateRay(100.0f, 0.0f, 200, 100), bottom = c.generateRay(100.0f, 100.0f, 200, 100);
  EXPECT_NEAR(angleBetween(top.direction, forward) * 180.0f / kPi, fov / 2, 1e-3f);
  EXPECT_GT(top.direction.y, 0.0f) << "row 0 is the top of the image";
  EXPECT_LT(bottom.direction.y, 0.0f);
  Ray right = c.generateRay(200.0f, 50.0f, 200, 100);
  float expected = atanf(aspect * tanf(fov / 2 * kPi / 180.0f)) * 180.0f / kPi;
  EXPECT_NEAR(angleBetween(right.direction, forward) * 180.0f / kPi, expected, 1e-3f);
  EXPECT_GT(right.direction.x, 0.0f) << "looking down -z with +y up, image right is +x";
}

// Where a ray meets the plane z = planeZ.
Vec3 onPlane(const Ray& r, float planeZ) { return r.origin + r.direction * ((planeZ - r.origin.z) / r.direction.z); }

CameraDescription orthographicView(float halfHeight) {
  CameraDescription d;
  d.eye = {1, 2, 3};
  d.target = {1, 2, -7};  // looking down -z, +y up: image right is +x
  d.projection = Projection::Orthographic;
  d.orthographicHalfHeight = halfHeight;
  return d;
}

TEST(Camera, OrthographicRaysAreParallelAndSpanTheImageInWorldUnits) {
  // A plane seen orthographically: every ray is the view direction, and the image covers 2 * halfHeight by
  // 2 * halfHeight * aspect of the plane, whatever its distance.
  const Camera c = orthographicView(2.0f).toCamera(1.5f);
  const int width = 300, height = 200;
  for (float planeZ : {-5.0f, -500.0f}) {
    for (Vec2 px : {Vec2{0, 0}, Vec2{300, 200}, Vec2{150, 100}, Vec2{37.5f, 180}}) {
      const Ray r = c.generateRay(px.x, px.y, width, height);
      EXPECT_NEAR(r.direction.x, 0.0f, 1e-6f);
      EXPECT_NEAR(r.direction.y, 0.0f, 1e-6f);
      EXPECT_NEAR(r.direction.z, -1.0f, 1e-6f);
      const Vec3 p = onPlane(r, planeZ);
      EXPECT_NEAR(p.x, 1.0f + (2.0f * px.x / width - 1.0f) * 3.0f, 1e-4f) << px.x;
      EXPECT_NEAR(p.y, 2.0f + (1.0f - 2.0f * px.y / height) * 2.0f, 1e-4f) << px.y;
    }
  }
}

TEST(Camera, OrthographicThinLensFocusesItsFocusPlane) {
  CameraDescription d = orthographicView(1.0f);
  d.apertureRadius = 0.5f;
  d.focusDistance = 4.0f;
  const Camera c = d.toCamera(1.0f);
  const Ray pinhole = orthographicView(1.0f).toCamera(1.0f).generateRay(20, 70, 100, 100);
  for (Vec2 u : {Vec2{0.1f, 0.9f}, Vec2{0.7f, 0.3f}}) {
    const Ray r = c.generateRay(20, 70, 100, 100, u);
    EXPECT_GT(length(r.origin - pinhole.origin), 0.01f) << "the lens moves the origin";
    const Vec3 sharp = onPlane(r, 3.0f - 4.0f), expected = onPlane(pinhole, 3.0f - 4.0f);
    EXPECT_NEAR(length(sharp - expected), 0.0f, 1e-5f) << "rays through the lens meet on the focus plane";
  }
}

TEST(Camera, ImageShiftMovesTheImageOffTheAxis) {
  // A shift of (0.5, -1) half heights: the perspective image's centre looks half a half-height right and one
  // down; the orthographic one starts there.
  CameraDescription perspective;
  perspective.eye = {0, 0, 0};
  perspective.target = {0, 0, -1};
  perspective.verticalFovDegrees = 90.0f;
  perspective.imageShift = {0.5f, -1.0f};
  const Ray centre = perspective.toCamera(2.0f).generateRay(100, 50, 200, 100);
  const Vec3 p = onPlane(centre, -1.0f);
  EXPECT_NEAR(p.x, 0.5f, 1e-5f);
  EXPECT_NEAR(p.y, -1.0f, 1e-5f);
  CameraDescription orthographic = orthographicView(2.0f);
  orthographic.imageShift = {0.5f, -1.0f};
  const Ray o = orthographic.toCamera(2.0f).generateRay(100, 50, 200, 100);
  EXPECT_NEAR(o.origin.x, 1.0f + 0.5f * 2.0f, 1e-5f);
  EXPECT_NEAR(o.origin.y, 2.0f - 1.0f * 2.0f, 1e-5f);
}

}  // namespace
}  // namespace candela
