#pragma once
#include <cstdint>

namespace candela {

// How much work one frame does.
struct FramePlan {
  uint32_t width = 0;
  uint32_t height = 0;
  uint32_t samplesPerPixel = 1;
  bool preview = false;  // reduced while the camera moves
};

// Keeps the viewer responsive: while the camera moves (and for a short settle time after it last moved) a frame
// renders one sample per pixel at a resolution divided so that it fits the frame budget, judged by the measured
// cost of earlier frames; once the camera rests, frames render the full image with the chosen samples per frame.
// The divisor is fixed at the start of each motion, so the preview does not change resolution while it lasts.
class InteractivePolicy {
 public:
  explicit InteractivePolicy(double frameBudgetSeconds = 1.0 / 30.0, double settleSeconds = 0.2);

  FramePlan plan(uint32_t fullWidth, uint32_t fullHeight, uint32_t samplesPerFrame, bool cameraMoved, double now);
  void recordFrame(const FramePlan& plan, double seconds);

  double secondsPerSample() const { return secondsPerSample_; }  // per pixel sample, smoothed
  static constexpr uint32_t kMaxDivisor = 8;

 private:
  uint32_t divisorFor(uint32_t width, uint32_t height) const;

  double budget_;
  double settle_;
  double lastMotion_ = -1e300;
  bool inPreview_ = false;
  uint32_t divisor_ = 1;
  double secondsPerSample_ = 0.0;
};

}  // namespace candela
