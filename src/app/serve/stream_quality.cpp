#include "app/serve/stream_quality.h"

#include <algorithm>
#include <cmath>

namespace candela {

void StreamQuality::recordDelivery(size_t bytes, double seconds, bool moving) {
  if (seconds <= 0.0) return;
  const double rate = double(bytes) / seconds;
  bytesPerSecond_ = bytesPerSecond_ == 0.0 ? rate : 0.8 * bytesPerSecond_ + 0.2 * rate;
  if (!moving) return;
  if (seconds > budget_) {
    if (movingQuality_ > kMinMovingQuality)
      movingQuality_ = std::max(kMinMovingQuality, movingQuality_ - kQualityStep);
    else
      movingDivisor_ = std::min(kMaxExtraDivisor, movingDivisor_ * 2);
  } else if (seconds < 0.5 * budget_) {
    if (movingDivisor_ > 1)
      movingDivisor_ /= 2;
    else
      movingQuality_ = std::min(kMaxMovingQuality, movingQuality_ + kQualityStep / 2);
  }
}

H264Settings StreamQuality::videoSettings(bool moving, double framesPerSecond) const {
  H264Settings settings;
  if (framesPerSecond > 0.0)
    settings.framesPerSecond =
        kFrameRateStep * uint32_t(std::ceil(std::min(framesPerSecond, double(kMaxFrameRate)) / kFrameRateStep));
  if (!moving) settings.framesPerSecond = std::min(settings.framesPerSecond, kRestFrameRate);
  settings.deblocking = !moving;
  // What the link carried, with room left for the other messages and the variation between frames.
  const double linkKilobits = 0.8 * 8.0 * bytesPerSecond_ / 1000.0;
  settings.maxKilobitsPerSecond =
      bytesPerSecond_ == 0.0 ? kMaxVideoKilobits
                             : uint32_t(std::clamp(linkKilobits, double(kMinVideoKilobits), double(kMaxVideoKilobits)));
  settings.rateFactor = moving ? kMovingRateFactor + 9.0f * float(kMaxMovingQuality - movingQuality_) /
                                                         float(kMaxMovingQuality - kMinMovingQuality)
                               : kRestRateFactor;
  return settings;
}

}  // namespace candela
