#pragma once
#include <cstdint>
#include <string>

#include "app/interactive/camera_input.h"
#include "app/interactive/frame_images.h"
#include "app/interactive/interactive_policy.h"

namespace candela {

// What a front end asks of one frame.
struct FrameRequest {
  uint32_t width = 0, height = 0;  // of the view the image fills, in pixels
  double now = 0.0;                // seconds on a steady clock
  double seconds = 0.0;            // since the last frame: the step of the animation and of the fly keys
};

// The parts of a frame that differ between front ends (the window of candela view, the page of candela serve);
// InteractiveRenderer::step calls them in this order.
class FrontEnd {
 public:
  virtual ~FrontEnd() = default;
  // After the animation's pose, before the camera is taken: feeds the input that came since the last frame to the
  // renderer's CameraInput (and acts on keys that frame or reset the camera); returns the fly keys held now.
  virtual FlyKeys takeInput() = 0;
  // May shrink the plan further (candela serve: a preview over a slow connection).
  virtual void adjustPlan(FramePlan&) {}
  // Shows the rendered frame: uploads it to the window's texture, or tone maps it for the browser.
  virtual void present(FrameImages& frame) = 0;
  // Tells the user something went wrong or was done.
  virtual void report(const std::string& message, bool isError) = 0;
};

}  // namespace candela
