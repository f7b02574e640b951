#include "app/schedule/sample_dispenser.h"

#include <algorithm>

#include "app/checkpoint/stop_signals.h"

namespace candela {

SampleDispenser::SampleDispenser(uint32_t first, uint32_t end, const RenderControl& control, Clock::time_point jobStart)
    : next_(std::min(first, end)), end_(end), control_(control), jobStart_(jobStart), lastCheckpoint_(Clock::now()) {}

SampleDispenser::Pause SampleDispenser::pause(double batchSeconds) {
  if (next_ == end_) return Pause::End;
  const Clock::time_point now = Clock::now();
  if (StopOnSignals::requested() != 0) {
    ending_ = RenderEnd::Signal;
    return Pause::End;
  }
  const double elapsed = std::chrono::duration<double>(now - jobStart_).count();
  if (control_.timeLimitSeconds > 0.0 && elapsed + batchSeconds > control_.timeLimitSeconds) {
    ending_ = RenderEnd::TimeLimit;
    return Pause::End;
  }
  const double sinceCheckpoint = std::chrono::duration<double>(now - lastCheckpoint_).count();
  if (!control_.checkpointPath.empty() && control_.checkpointEverySeconds > 0.0 &&
      sinceCheckpoint >= control_.checkpointEverySeconds)
    return Pause::Checkpoint;
  return Pause::None;
}

uint32_t SampleDispenser::take(uint32_t count) {
  const uint32_t first = next_;
  next_ += std::min(count, remaining());
  return first;
}

}  // namespace candela
