#pragma once
#include <cstddef>
#include <cstdint>

#include "io/video/h264_encoder.h"

namespace candela {

// How the frames sent while the camera moves adapt to the connection: each frame's delivery time (from sending
// to the browser's acknowledgement that it drew it) is compared with the frame budget. Slow deliveries lower the
// JPEG quality step by step, and once it is at its floor, halve the preview's resolution; quick ones raise them
// back. Frames at rest always go at full quality and resolution: there the picture matters more than the rate.
// The H.264 stream follows the same steps (its rate factor rises as the JPEG quality falls) and keeps its rate
// under what the link delivered, at the frame rate measured.
class StreamQuality {
 public:
  explicit StreamQuality(double frameBudgetSeconds = 1.0 / 30.0) : budget_(frameBudgetSeconds) {}

  void recordDelivery(size_t bytes, double seconds, bool moving);
  int jpegQuality(bool moving) const { return moving ? movingQuality_ : kRestQuality; }
  uint32_t resolutionDivisor(bool moving) const { return moving ? movingDivisor_ : 1; }
  double bytesPerSecond() const { return bytesPerSecond_; }  // smoothed; 0 until measured
  // `framesPerSecond`: the rate frames are sent at, 0 where not measured yet (then H264Settings' default). It is
  // rounded up to a multiple of kFrameRateStep, so that the cap holds and the encoder is not reconfigured for every
  // small change.
  H264Settings videoSettings(bool moving, double framesPerSecond) const;

  static constexpr int kRestQuality = 92;
  static constexpr int kMaxMovingQuality = 80;
  static constexpr int kMinMovingQuality = 35;
  static constexpr int kQualityStep = 10;
  static constexpr uint32_t kMaxExtraDivisor = 4;
  static constexpr float kRestRateFactor = 18.0f;
  static constexpr float kMovingRateFactor = 22.0f;  // at the best moving JPEG quality; 9 more at the worst
  static constexpr uint32_t kMaxVideoKilobits = 20000;
  static constexpr uint32_t kMinVideoKilobits = 1000;
  static constexpr uint32_t kFrameRateStep = 5;
  static constexpr uint32_t kMaxFrameRate = 1000;

 private:
  double budget_;
  int movingQuality_ = 70;
  uint32_t movingDivisor_ = 1;
  double bytesPerSecond_ = 0.0;
};

}  // namespace candela
