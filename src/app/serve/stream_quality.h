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
//
// At rest the video's frames differ from one another only by the accumulation's shrinking noise: sent 60 times a
// second, they spend the rate on that noise and each gets too few bits to sharpen the picture (DamagedHelmet at
// 1080p: 35.9 dB PSNR at 18.8 Mbit/s). So at rest the stream goes at kRestFrameRate frames a second at most
// (ServeLoop holds the others back, and sends a frame at once when input comes), each with the rate's share at
// that rate, a lower rate factor to spend it, and the deblocking filter (docs/performance.md, 'The video stream's
// quality on rendered frames').
class StreamQuality {
 public:
  explicit StreamQuality(double frameBudgetSeconds = 1.0 / 30.0) : budget_(frameBudgetSeconds) {}

  void recordDelivery(size_t bytes, double seconds, bool moving);
  int jpegQuality(bool moving) const { return moving ? movingQuality_ : kRestQuality; }
  uint32_t resolutionDivisor(bool moving) const { return moving ? movingDivisor_ : 1; }
  double bytesPerSecond() const { return bytesPerSecond_; }  // smoothed; 0 until measured
  // `framesPerSecond`: the rate frames are sent at, 0 where not measured yet (then H264Settings' default). It is
  // rounded up to a multiple of kFrameRateStep, so that the cap holds and the encoder is not reconfigured for every
  // small change; at rest it is kRestFrameRate at most.
  H264Settings videoSettings(bool moving, double framesPerSecond) const;

  static constexpr int kRestQuality = 92;
  static constexpr int kMaxMovingQuality = 80;
  static constexpr int kMinMovingQuality = 35;
  static constexpr int kQualityStep = 10;
  static constexpr uint32_t kMaxExtraDivisor = 4;
  static constexpr float kRestRateFactor = 12.0f;
  static constexpr uint32_t kRestFrameRate = 20;
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
