#include <gtest/gtest.h>

#include <cmath>

#include "app/interactive/orbit_camera.h"

namespace candela {
namespace {

constexpr float kEps = 1e-4f;

void expectNear(Vec3 a, Vec3 b, float tolerance = kEps) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

Bounds3 cube(float halfSide, Vec3 centre = {0, 0, 0}) {
  Bounds3 b;
  b.extend(centre - Vec3{halfSide, halfSide, halfSide});
  b.extend(centre + Vec3{halfSide, halfSide, halfSide});
  return b;
}

CameraDescription home(Vec3 eye = {0, 1, 5}, Vec3 target = {0, 1, 0}, Vec3 up = {0, 1, 0}) {
  CameraDescription d;
  d.eye = eye;
  d.target = target;
  d.up = up;
  d.verticalFovDegrees = 40.0f;
  return d;
}

// Where a world point lands on an image of the given size, in pixels from the top-left corner.
Vec2 project(const Camera& c, Vec3 p, float width, float height) {
  Vec3 d = p - c.position;
  float z = dot(d, c.forward);
  float sx = dot(d, c.right) / dot(c.right, c.right) / z;
  float sy = dot(d, c.up) / dot(c.up, c.up) / z;
  return {(sx + 1.0f) * 0.5f * width, (1.0f - sy) * 0.5f * height};
}

TEST(OrbitCamera, StartsAtTheScenesCamera) {
  for (Vec3 up : {Vec3{0, 1, 0}, Vec3{0, 0, 1}, Vec3{1, 0, 0}}) {
    CameraDescription d = home({3, -2, 4}, {0.5f, 0.25f, -1}, up);
    OrbitCamera orbit(d, cube(2));
    Camera expected = d.toCamera(1.5f), actual = orbit.camera(1.5f);
    expectNear(actual.position, expected.position);
    expectNear(actual.forward, expected.forward);
    expectNear(actual.right, expected.right);
    expectNear(actual.up, expected.up);
    EXPECT_EQ(actual.lensRadius, 0.0f);
  }
}

TEST(OrbitCamera, AThinLensFocusesOnTheTargetUnlessTold) {
  CameraDescription d = home();
  d.apertureRadius = 0.05f;
  OrbitCamera orbit(d, cube(2));
  EXPECT_EQ(orbit.camera(1.0f).lensRadius, 0.05f);
  EXPECT_NEAR(orbit.camera(1.0f).focusDistance, d.toCamera(1.0f).focusDistance, kEps);
  orbit.dolly(2.0f);
  EXPECT_NEAR(orbit.camera(1.0f).focusDistance, orbit.distance(), kEps);
  d.focusDistance = 3.0f;
  OrbitCamera fixed(d, cube(2));
  fixed.dolly(2.0f);
  EXPECT_EQ(fixed.camera(1.0f).focusDistance, 3.0f);
}

TEST(OrbitCamera, OrbitKeepsTargetAndDistance) {
  OrbitCamera orbit(home(), cube(2));
  orbit.orbit(137.0f, -42.0f);
  expectNear(orbit.target(), {0, 1, 0});
  EXPECT_NEAR(length(orbit.position() - orbit.target()), 5.0f, kEps);
  expectNear(orbit.forward(), normalize(orbit.target() - orbit.position()));
}

TEST(OrbitCamera, DraggingRightTurnsTheSceneRight) {
  for (Vec3 up : {Vec3{0, 1, 0}, Vec3{0, -1, 0}, Vec3{0, 0, 1}, Vec3{0.6f, 0.0f, -0.8f}}) {
    OrbitCamera orbit(home({0.3f, 0.2f, 4.0f}, {0, 0, 0}, up), cube(2));
    Camera before = orbit.camera(1.0f);
    orbit.orbit(50.0f, 0.0f);
    // The camera moves to its left, so the scene appears to turn the way the mouse went.
    EXPECT_LT(dot(orbit.position() - before.position, before.right), 0.0f);
    orbit.reset();
    orbit.orbit(0.0f, 50.0f);  // dragging down: the camera rises
    EXPECT_GT(dot(orbit.position() - before.position, up), 0.0f);
  }
}

TEST(OrbitCamera, NoFlipAtThePoles) {
  for (float direction : {1.0f, -1.0f}) {
    OrbitCamera orbit(home(), cube(2));
    Vec3 previousForward = orbit.forward();
    // Far past the pole in small steps: the camera's up never turns against the world's and the view never jumps.
    for (int i = 0; i < 400; ++i) {
      orbit.orbit(3.0f, direction * 5.0f);
      Camera c = orbit.camera(1.0f);
      ASSERT_GT(dot(normalize(c.up), Vec3{0, 1, 0}), 0.0f);
      ASSERT_TRUE(isFinite(c.right) && length(c.right) > 0.1f);
      ASSERT_GT(dot(orbit.forward(), previousForward), 0.99f);
      previousForward = orbit.forward();
    }
    EXPECT_NEAR(std::fabs(orbit.forward().y), std::sin(OrbitCamera::kMaxPitch), 1e-3f);
  }
}

TEST(OrbitCamera, PanMovesThePointAtTargetDepthWithTheCursor) {
  OrbitCamera orbit(home(), cube(2));
  const float width = 400.0f, height = 300.0f;
  const Vec3 anchor = orbit.target() + Vec3{0.3f, -0.2f, 0.0f};  // at the target's depth
  Vec2 before = project(orbit.camera(width / height), anchor, width, height);
  Vec3 forwardBefore = orbit.forward();
  orbit.pan(25.0f, -10.0f, height);
  Vec2 after = project(orbit.camera(width / height), anchor, width, height);
  EXPECT_NEAR(after.x - before.x, 25.0f, 1e-2f);
  EXPECT_NEAR(after.y - before.y, -10.0f, 1e-2f);
  expectNear(orbit.forward(), forwardBefore);
  EXPECT_NEAR(orbit.distance(), 5.0f, kEps);
}

TEST(OrbitCamera, DollyScalesTheDistanceAndKeepsTheDirection) {
  OrbitCamera orbit(home(), cube(2));
  Vec3 forward = orbit.forward();
  orbit.dolly(2.0f);
  EXPECT_NEAR(orbit.distance(), 5.0f * OrbitCamera::kDollyStep * OrbitCamera::kDollyStep, kEps);
  orbit.dolly(-2.0f);
  EXPECT_NEAR(orbit.distance(), 5.0f, kEps);
  expectNear(orbit.forward(), forward);
  expectNear(orbit.target(), {0, 1, 0});
  orbit.dolly(1e4f);  // stops short of the target
  EXPECT_GT(orbit.distance(), 0.0f);
  EXPECT_TRUE(isFinite(orbit.position()));
}

TEST(OrbitCamera, FlySpeedScalesWithTheScene) {
  for (float size : {0.1f, 1.0f, 100.0f}) {
    CameraDescription d = home(Vec3{0, 1, 5} * size, Vec3{0, 1, 0} * size);
    OrbitCamera orbit(d, cube(2.0f * size));
    Vec3 start = orbit.position(), forward = orbit.forward();
    orbit.fly({0, 0, 1}, 0.5f);
    Vec3 moved = orbit.position() - start;
    EXPECT_NEAR(length(moved), 0.5f * orbit.flySpeed(), 1e-3f * size);
    EXPECT_NEAR(orbit.flySpeed(), OrbitCamera::kFlySpeedPerRadius * cube(2.0f * size).radius(), 1e-3f * size);
    expectNear(normalize(moved), forward);
    orbit.fly({0, 1, 0}, 1.0f);  // E rises along the world's up
    EXPECT_GT(orbit.position().y, start.y);
  }
}

TEST(OrbitCamera, FrameSceneFitsTheBoundsInView) {
  const Bounds3 bounds = cube(1.0f, {10, -3, 2});
  OrbitCamera orbit(home({0, 0, 50}, {0, 0, 40}), bounds);
  orbit.orbit(80.0f, 30.0f);
  orbit.frameScene();
  expectNear(orbit.target(), bounds.centre());
  const float width = 320.0f, height = 240.0f;
  Camera c = orbit.camera(width / height);
  for (int corner = 0; corner < 8; ++corner) {
    Vec3 p{corner & 1 ? bounds.hi.x : bounds.lo.x, corner & 2 ? bounds.hi.y : bounds.lo.y,
           corner & 4 ? bounds.hi.z : bounds.lo.z};
    Vec2 s = project(c, p, width, height);
    EXPECT_TRUE(s.x >= 0 && s.x <= width && s.y >= 0 && s.y <= height) << "corner " << corner;
  }
}

TEST(OrbitCamera, ResetReturnsHome) {
  OrbitCamera orbit(home(), cube(2));
  orbit.orbit(10, 20);
  orbit.pan(5, 5, 100);
  orbit.dolly(3);
  orbit.fly({1, 0, 0}, 1);
  orbit.reset();
  expectNear(orbit.position(), {0, 1, 5});
  expectNear(orbit.target(), {0, 1, 0});
}

TEST(OrbitCamera, EmptySceneStillMoves) {
  OrbitCamera orbit(home(), Bounds3{});
  orbit.fly({0, 0, 1}, 1.0f);
  orbit.frameScene();  // nothing to frame: stays put
  EXPECT_TRUE(isFinite(orbit.position()));
  EXPECT_GT(orbit.flySpeed(), 0.0f);
}

}  // namespace
}  // namespace candela
