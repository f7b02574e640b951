#include <gtest/gtest.h>

#include "app/interactive/camera_input.h"

namespace candela {
namespace {

CameraDescription home() {
  CameraDescription d;
  d.eye = {0, 1, 5};
  d.target = {0, 1, 0};
  return d;
}

Bounds3 unitCube() {
  Bounds3 b;
  b.extend({-1, -1, -1});
  b.extend({1, 1, 1});
  return b;
}

bool same(Vec3 a, Vec3 b) { return length(a - b) < 1e-6f; }

TEST(CameraInput, DragsAndWheelMapToOrbitPanAndDolly) {
  struct Case {
    MouseButton button;
    bool orbits;
  };
  for (Case c : {Case{MouseButton::Right, true}, Case{MouseButton::Left, true}, Case{MouseButton::Middle, false}}) {
    OrbitCamera camera(home(), unitCube()), expected(home(), unitCube());
    CameraInput input;
    input.buttonPressed(c.button, 10, 10, /*overImage=*/true);
    input.cursorMoved(30, 15);
    input.cursorMoved(40, 5);
    input.buttonReleased(c.button);
    input.cursorMoved(90, 90);  // after the release: ignored
    EXPECT_TRUE(input.apply(camera, {}, 0.016f, 200.0f));
    if (c.orbits)
      expected.orbit(30, -5);
    else
      expected.pan(30, -5, 200.0f);
    EXPECT_TRUE(same(camera.position(), expected.position()));
    EXPECT_TRUE(same(camera.target(), expected.target()));
  }
  OrbitCamera camera(home(), unitCube());
  CameraInput input;
  input.wheel(2.0, true);
  input.wheel(1.0, false);  // over the panel
  EXPECT_TRUE(input.apply(camera, {}, 0.016f, 200.0f));
  EXPECT_NEAR(camera.distance(), 5.0f * OrbitCamera::kDollyStep * OrbitCamera::kDollyStep, 1e-5f);
}

TEST(CameraInput, DragStartedOverThePanelIsIgnored) {
  OrbitCamera camera(home(), unitCube());
  CameraInput input;
  input.buttonPressed(MouseButton::Right, 500, 10, /*overImage=*/false);
  input.cursorMoved(100, 50);
  EXPECT_FALSE(input.dragging());
  EXPECT_FALSE(input.apply(camera, {}, 0.016f, 200.0f));
  EXPECT_TRUE(same(camera.position(), {0, 1, 5}));
}

TEST(CameraInput, AnotherButtonDoesNotEndTheDrag) {
  CameraInput input;
  input.buttonPressed(MouseButton::Right, 0, 0, true);
  input.buttonPressed(MouseButton::Middle, 0, 0, true);
  input.buttonReleased(MouseButton::Middle);
  EXPECT_TRUE(input.dragging());
  input.buttonReleased(MouseButton::Right);
  EXPECT_FALSE(input.dragging());
}

TEST(CameraInput, FlyKeysMoveForTheFrameTime) {
  OrbitCamera camera(home(), unitCube());
  CameraInput input;
  FlyKeys keys;
  EXPECT_FALSE(input.apply(camera, keys, 0.1f, 200.0f));
  keys.forward = true;
  EXPECT_TRUE(input.apply(camera, keys, 0.1f, 200.0f));
  EXPECT_NEAR(camera.position().z, 5.0f - 0.1f * camera.flySpeed(), 1e-5f);
  keys.back = true;  // opposite keys cancel
  EXPECT_FALSE(input.apply(camera, keys, 0.1f, 200.0f));
}

}  // namespace
}  // namespace candela
