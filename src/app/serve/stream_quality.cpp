#include "app/serve/stream_quality.h"

#include <algorithm>

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

}  // namespace candela
