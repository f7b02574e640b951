#include "app/interactive/camera_input.h"

namespace candela {

void CameraInput::buttonPressed(MouseButton button, double x, double y, bool overImage) {
  if (drag_ != Drag::None || !overImage) return;
  drag_ = button == MouseButton::Middle ? Drag::Pan : Drag::Orbit;
  dragButton_ = button;
  lastX_ = x;
  lastY_ = y;
}

void CameraInput::buttonReleased(MouseButton button) {
  if (drag_ != Drag::None && button == dragButton_) drag_ = Drag::None;
}

void CameraInput::cursorMoved(double x, double y) {
  if (drag_ == Drag::Orbit) {
    orbitX_ += x - lastX_;
    orbitY_ += y - lastY_;
  } else if (drag_ == Drag::Pan) {
    panX_ += x - lastX_;
    panY_ += y - lastY_;
  }
  lastX_ = x;
  lastY_ = y;
}

void CameraInput::wheel(double steps, bool overImage) {
  if (overImage) wheel_ += steps;
}

bool CameraInput::apply(OrbitCamera& camera, const FlyKeys& keys, float seconds, float viewportHeight) {
  bool moved = false;
  if (orbitX_ != 0.0 || orbitY_ != 0.0) {
    camera.orbit(float(orbitX_), float(orbitY_));
    moved = true;
  }
  if (panX_ != 0.0 || panY_ != 0.0) {
    camera.pan(float(panX_), float(panY_), viewportHeight);
    moved = true;
  }
  if (wheel_ != 0.0) {
    camera.dolly(float(wheel_));
    moved = true;
  }
  orbitX_ = orbitY_ = panX_ = panY_ = wheel_ = 0.0;

  const Vec3 fly{float(keys.right) - float(keys.left), float(keys.up) - float(keys.down),
                 float(keys.forward) - float(keys.back)};
  if ((fly.x != 0.0f || fly.y != 0.0f || fly.z != 0.0f) && seconds > 0.0f) {
    camera.fly(fly, seconds);
    moved = true;
  }
  return moved;
}

}  // namespace candela
