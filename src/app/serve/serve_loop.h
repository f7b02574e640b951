#pragma once
#include <atomic>
#include <chrono>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "app/interactive/interactive_renderer.h"
#include "app/serve/client_hub.h"
#include "app/serve/frame_encoding.h"
#include "app/serve/stream_quality.h"
#include "io/images/striped_jpeg.h"
#include "io/video/h264_encoder.h"

namespace candela {

// The render side of candela serve: the interactive renderer, steered by the messages of the browser that holds
// control, rendering a frame whenever a browser is ready for one (client_hub.h) and never otherwise, so that the
// network's speed sets how many frames are made, not how many wait in a queue.
class ServeLoop : private FrontEnd {
 public:
  // Loads the scene and makes the backend; throws std::runtime_error with one sentence when either fails.
  ServeLoop(const InteractiveOptions& options, ClientHub& hub);
  // Runs until `stop` becomes true, or until options.frames frames have been rendered (as candela view renders
  // them: the frames the video holds back at rest count, so that both make the same image).
  void run(const std::atomic<bool>& stop);
  // Writes the --screenshot once run() has returned; throws std::runtime_error when it cannot (no frame was
  // rendered, or the file cannot be written).
  void writeExitFiles();

 private:
  // FrontEnd: the input came with the messages before the frame; the frame is tone mapped where the film is
  // (FrameImages::display), then encoded as JPEG stripes in parallel (io/images/striped_jpeg.h).
  FlyKeys takeInput() override { return flyKeys_; }
  void adjustPlan(FramePlan& plan) override;
  void present(FrameImages& frame) override;
  void report(const std::string& message, bool isError) override;

  void greet(uint64_t client);
  void handle(const IncomingMessage& incoming);
  void applySettings(const SettingsMessage& settings);
  void act(uint64_t client, ActionMessage::Kind kind);
  void renderFrame(double now);
  nlohmann::json controlsJson() const;

  InteractiveOptions options_;
  ClientHub& hub_;
  InteractiveRenderer renderer_;
  FlyKeys flyKeys_;
  StreamQuality quality_;
  uint32_t viewWidth_, viewHeight_;  // the controlling browser's view, in device pixels
  bool environmentEdited_ = false;   // since the backend last got the environment
  bool materialsEdited_ = false;
  uint64_t controlChanges_ = 0;
  uint64_t framesRendered_ = 0;
  uint64_t framesSent_ = 0;
  // The frame present() made, for renderFrame to send: as JPEG stripes, as the video's next access unit, or both,
  // as the clients ready for it need (ClientHub::frameNeeds).
  struct PresentedFrame {
    std::optional<StripedJpeg> jpeg;
    std::optional<H264Frame> video;
    double postMilliseconds = 0.0;
  };
  StripedJpegEncoder jpegEncoder_;
  H264Encoder videoEncoder_;
  FrameNeeds needs_;  // of the frame being made
  // The stream settings of the frame being made (adjustPlan), for its encoding and its header.
  int jpegQuality_ = 0;
  H264Settings videoSettings_;
  uint64_t lastVideoFrame_ = 0;
  // At rest the video goes at StreamQuality::kRestFrameRate at most: the frames rendered sooner than that after
  // the last access unit add their samples but are not encoded, unless input came since (then a frame goes at
  // once, as while moving).
  std::optional<double> lastVideoTime_;
  bool inputSinceVideo_ = true;
  bool holdVideo_ = false;  // the frame being made
  PresentedFrame presented_;
  bool firstFrame_ = true;
  double frameTime_ = 0.0;      // of the frame being made
  double lastFrameTime_ = 0.0;  // of the last frame rendered
  std::optional<double> lastSentTime_;
  bool lastSentMoving_ = false;
  // Between frames sent, smoothed: all of them (the frame header's rate, and the video's at rest), and those
  // between two moving frames (the video's while moving, which the slower frames at rest must not lower).
  double msPerFrame_ = 0.0;
  double msPerMovingFrame_ = 0.0;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace candela
