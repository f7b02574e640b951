#include "app/interactive/orbit_camera.h"

#include <algorithm>
#include <cmath>

namespace candela {

namespace {

// A distance below which dolly stops, and above which it stops, relative to the scene's radius.
constexpr float kMinDistancePerRadius = 1e-3f;
constexpr float kMaxDistancePerRadius = 1e3f;

}  // namespace

OrbitCamera::OrbitCamera(const CameraDescription& home, const Bounds3& sceneBounds)
    : home_(home), bounds_(sceneBounds) {
  up_ = normalize(home.up);
  Frame frame = Frame::fromNormal(up_);
  axisX_ = frame.s;
  axisZ_ = frame.t;
  const float eyeTarget = length(home.eye - home.target);
  sceneRadius_ =
      sceneBounds.empty() || sceneBounds.radius() <= 0.0f ? std::max(eyeTarget, 1e-3f) : sceneBounds.radius();
  reset();
}

void OrbitCamera::reset() {
  target_ = home_.target;
  const Vec3 offset = home_.eye - home_.target;
  distance_ = std::max(length(offset), kMinDistancePerRadius * sceneRadius_);
  const Vec3 d = length(offset) > 0.0f ? offset / length(offset) : axisZ_;
  pitch_ = std::clamp(std::asin(std::clamp(dot(d, up_), -1.0f, 1.0f)), -kMaxPitch, kMaxPitch);
  yaw_ = std::atan2(dot(d, axisX_), dot(d, axisZ_));
}

Vec3 OrbitCamera::offsetDirection() const {
  const float c = std::cos(pitch_);
  return (axisZ_ * std::cos(yaw_) + axisX_ * std::sin(yaw_)) * c + up_ * std::sin(pitch_);
}

Vec3 OrbitCamera::position() const { return target_ + offsetDirection() * distance_; }
Vec3 OrbitCamera::forward() const { return -offsetDirection(); }

Camera OrbitCamera::camera(float aspect) const {
  // The scene camera's projection and lens at the orbit's position. A thin lens focuses where the scene's camera
  // said, or else on the target (at distance_), wherever it has moved.
  CameraDescription d = description();
  d.up = up_;
  if (!(d.focusDistance > 0.0f)) d.focusDistance = distance_;
  return d.toCamera(aspect);
}

CameraDescription OrbitCamera::description() const {
  CameraDescription d = home_;
  d.eye = position();
  d.target = target_;
  return d;
}

void OrbitCamera::orbit(float dxPixels, float dyPixels) {
  yaw_ = std::remainder(yaw_ + dxPixels * kRadiansPerPixel, 2.0f * kPi);
  pitch_ = std::clamp(pitch_ + dyPixels * kRadiansPerPixel, -kMaxPitch, kMaxPitch);
}

void OrbitCamera::pan(float dxPixels, float dyPixels, float viewportHeightPixels) {
  const Camera c = camera(1.0f);
  const float tanHalf = std::tan(0.5f * home_.verticalFovDegrees * kPi / 180.0f);
  const float worldPerPixel = 2.0f * distance_ * tanHalf / std::max(viewportHeightPixels, 1.0f);
  const Vec3 right = normalize(c.right), up = normalize(c.up);
  target_ += (right * -dxPixels + up * dyPixels) * worldPerPixel;
}

void OrbitCamera::dolly(float steps) {
  distance_ = std::clamp(distance_ * std::pow(kDollyStep, steps), kMinDistancePerRadius * sceneRadius_,
                         kMaxDistancePerRadius * sceneRadius_);
}

void OrbitCamera::fly(Vec3 direction, float seconds) {
  const Camera c = camera(1.0f);
  const Vec3 move = normalize(c.right) * direction.x + up_ * direction.y + forward() * direction.z;
  if (length(move) == 0.0f) return;
  target_ += normalize(move) * (flySpeed() * seconds);
}

void OrbitCamera::frameScene() {
  if (bounds_.empty()) return;
  // The bounding sphere touches the top and bottom of the view; wider images show more around it.
  const float sinHalf = std::sin(0.5f * home_.verticalFovDegrees * kPi / 180.0f);
  target_ = bounds_.centre();
  distance_ = sceneRadius_ / sinHalf;
}

}  // namespace candela
