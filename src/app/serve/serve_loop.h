#pragma once
#include <atomic>
#include <chrono>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "app/interactive/camera_input.h"
#include "app/interactive/interactive_policy.h"
#include "app/interactive/orbit_camera.h"
#include "app/interactive/render_session.h"
#include "app/interactive/viewer_controls.h"
#include "app/interactive/viewer_denoiser.h"
#include "app/serve/client_hub.h"
#include "app/serve/serve_options.h"
#include "app/serve/stream_quality.h"

namespace candela {

// The render side of candela serve: the viewer's session, camera and controls, steered by the messages of the
// browser that holds control, rendering a frame whenever a browser is ready for one (client_hub.h) and never
// otherwise, so that the network's speed sets how many frames are made, not how many wait in a queue.
class ServeLoop {
 public:
  // Loads the scene and makes the backend; throws std::runtime_error with one sentence when either fails.
  ServeLoop(const ServeOptions& options, ClientHub& hub);
  // Runs until `stop` becomes true, or until options.frames frames have been sent.
  void run(const std::atomic<bool>& stop);

  const std::string& backendName() const { return backendName_; }

 private:
  void greet(uint64_t client);
  void handle(const IncomingMessage& incoming);
  void applySettings(const SettingsMessage& settings);
  void act(uint64_t client, ActionMessage::Kind kind);
  void renderFrame(double now);
  nlohmann::json controlsJson() const;
  void report(const std::string& message, bool isError);
  void prepareDenoiser();
  Image accumulatedImage();

  ServeOptions options_;
  ClientHub& hub_;
  RenderSession session_;
  ViewerDenoiser denoiser_;
  std::unique_ptr<OrbitCamera> camera_;
  CameraInput input_;
  FlyKeys flyKeys_;
  InteractivePolicy policy_;
  StreamQuality quality_;
  ViewerControls controls_;
  std::string backendName_;
  uint32_t viewWidth_, viewHeight_;  // the controlling browser's view, in device pixels
  bool environmentEdited_ = false;   // since the backend last got the environment
  bool materialsEdited_ = false;
  uint64_t controlChanges_ = 0;
  uint64_t framesSent_ = 0;
  Camera lastCamera_;
  bool firstFrame_ = true;
  double lastFrameTime_ = 0.0;
  double msPerFrame_ = 0.0;  // between frames sent, smoothed
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace candela
