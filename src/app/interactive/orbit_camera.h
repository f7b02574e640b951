#pragma once
#include "app/interactive/scene_summary.h"
#include "kernel/camera.h"
#include "scene/scene.h"

namespace candela {

// The viewer's camera: an eye orbiting a target point at some distance, described by yaw and pitch about the
// scene camera's up axis. Pitch stops short of the poles, so orbiting never flips the image. Translation speeds
// scale with the scene's bounding radius; rotation speeds are per pixel of mouse motion.
class OrbitCamera {
 public:
  OrbitCamera(const CameraDescription& home, const Bounds3& sceneBounds);

  void orbit(float dxPixels, float dyPixels);
  // Moves eye and target so the point at the target's depth follows the cursor.
  void pan(float dxPixels, float dyPixels, float viewportHeightPixels);
  // Positive steps move towards the target; each step scales the distance by kDollyStep.
  void dolly(float steps);
  // `direction` in camera terms: x right, y world up, z forward; its components are -1, 0 or 1.
  void fly(Vec3 direction, float seconds);
  // Looks at the centre of the scene's bounds from the current direction, with the bounds filling the view.
  void frameScene();
  // Back to the scene's own camera.
  void reset();

  Camera camera(float aspect) const;
  CameraDescription description() const;
  Vec3 position() const;
  Vec3 forward() const;
  Vec3 target() const { return target_; }
  float distance() const { return distance_; }
  float flySpeed() const { return kFlySpeedPerRadius * sceneRadius_; }  // world units per second

  static constexpr float kRadiansPerPixel = 0.005f;
  static constexpr float kMaxPitch = 1.5533430f;  // 89 degrees
  static constexpr float kDollyStep = 0.9f;
  static constexpr float kFlySpeedPerRadius = 0.5f;

 private:
  Vec3 offsetDirection() const;  // unit vector from target to eye

  CameraDescription home_;
  Bounds3 bounds_;
  float sceneRadius_ = 1.0f;
  Vec3 up_, axisX_, axisZ_;  // orthonormal world basis, up_ the camera's up
  Vec3 target_;
  float distance_ = 1.0f;
  float yaw_ = 0.0f;
  float pitch_ = 0.0f;
};

}  // namespace candela
