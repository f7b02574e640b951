#pragma once
#include "app/interactive/orbit_camera.h"

namespace candela {

enum class MouseButton { Left, Right, Middle };

// Which fly keys are held: W/S forward and back, A/D left and right, Q/E down and up.
struct FlyKeys {
  bool forward = false, back = false, left = false, right = false, down = false, up = false;
};

// Collects mouse events over the image between frames and applies them to an OrbitCamera once per frame.
// Left and right drags orbit, a middle drag pans, the wheel dollies. A drag that starts over the panel is
// ignored; one that starts over the image keeps going wherever the cursor goes until its button is released.
class CameraInput {
 public:
  void buttonPressed(MouseButton button, double x, double y, bool overImage);
  void buttonReleased(MouseButton button);
  void cursorMoved(double x, double y);
  void wheel(double steps, bool overImage);

  // Returns true when the camera moved.
  bool apply(OrbitCamera& camera, const FlyKeys& keys, float seconds, float viewportHeight);
  bool dragging() const { return drag_ != Drag::None; }

 private:
  enum class Drag { None, Orbit, Pan };
  Drag drag_ = Drag::None;
  MouseButton dragButton_ = MouseButton::Left;
  double lastX_ = 0.0, lastY_ = 0.0;
  double orbitX_ = 0.0, orbitY_ = 0.0;
  double panX_ = 0.0, panY_ = 0.0;
  double wheel_ = 0.0;
};

}  // namespace candela
