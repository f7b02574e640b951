#pragma once
#include <memory>
#include <string>

#include "app/interactive/camera_input.h"
#include "app/interactive/front_end.h"
#include "app/interactive/interactive_options.h"
#include "app/interactive/interactive_policy.h"
#include "app/interactive/orbit_camera.h"
#include "app/interactive/render_session.h"
#include "app/interactive/viewer_controls.h"
#include "app/interactive/viewer_denoiser.h"

namespace candela {

// What one frame did.
struct FrameOutcome {
  FramePlan plan;
  double seconds = 0.0;        // rendering, denoising, post-processing and presenting: the cost the plans are made with
  double renderSeconds = 0.0;  // of those, the backend's render of the frame's samples
};

// The interactive path tracer that candela view and candela serve share: the backend's session, the scene and its
// animation, the orbit camera and its input, the controls the panel edits, and the frame step. A front end feeds
// it input and controls, and calls step() for every frame it wants.
class InteractiveRenderer {
 public:
  // Makes the backend (saying which on stderr) and shows options.sceneSpec with its environment, camera and
  // animation. Throws std::runtime_error with one sentence when the backend, the scene or the animation named
  // cannot be had. An OptiX backend whose programs are still compiling for the GPU (a first start on the machine)
  // comes with the CPU backend, which renders the frames until the compile has ended (RenderSession).
  explicit InteractiveRenderer(const InteractiveOptions& options);

  // Shows another scene: a built-in one or a file, with its own environment, first camera and first animation.
  // Throws std::runtime_error (the scene stays) when it cannot be loaded.
  void openScene(const std::string& spec);

  // One frame: the animation's next pose (the view follows an animated scene camera until the input moves it), the
  // front end's input on the camera, the plan (InteractivePolicy), the render, the denoiser and the post settings'
  // images, then the front end presents it.
  FrameOutcome step(const FrameRequest& request, FrontEnd& frontEnd);

  // F: looks at the whole scene from where the camera is.
  void frameScene();
  // R: back to the scene's camera where the animation has it now; an animated one is followed again.
  void resetCamera();
  // The controls' environment and material overrides take effect from the next frame.
  void applyEnvironmentControls();
  void applyMaterialControls();

  // The accumulated image through the chosen denoiser.
  Image accumulatedImage();
  // The emission the bilateral filter keeps apart: empty where the backend does not record it (no AOVs).
  Image recordedEmission() const;
  // accumulatedImage() through the bilateral filter when it is on, on the host (postFiltered).
  Image postImage();
  // The accumulated image to a file (saveScreenshot): a .png tone mapped, an .exr or .pfm linear.
  void writeScreenshot(const std::string& path);

  ViewerControls& controls() { return controls_; }
  const ViewerControls& controls() const { return controls_; }
  CameraInput& input() { return input_; }
  const OrbitCamera& camera() const { return *camera_; }
  const RenderSession& session() const { return session_; }
  const std::string& sceneSpec() const { return sceneSpec_; }

  // The longest a fly step may be, so that a slow frame does not throw the camera far.
  static constexpr double kMaxFlyStep = 0.1;

 private:
  struct Backends {
    std::unique_ptr<Backend> backend, meanwhile;
  };
  static Backends makeBackends(const InteractiveOptions& options);
  InteractiveRenderer(const InteractiveOptions& options, Backends backends);

  void showScene(Scene scene, const std::string& spec);
  void prepareDenoiser(FrontEnd& frontEnd);

  InteractiveOptions options_;
  RenderSession session_;
  ViewerDenoiser denoiser_;
  InteractivePolicy policy_;
  ViewerControls controls_;
  std::unique_ptr<OrbitCamera> camera_;
  CameraInput input_;
  std::string sceneSpec_;
  Camera lastCamera_;
  bool sceneJustShown_ = true;
  bool followsSceneCamera_ = false;  // the view is the scene's animated camera, moved with each pose
};

}  // namespace candela
