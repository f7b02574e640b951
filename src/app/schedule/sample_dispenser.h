#pragma once
#include <chrono>
#include <cstdint>

#include "app/checkpoint/render_control.h"

namespace candela {

// Why a render ended.
enum class RenderEnd { Complete, TimeLimit, Signal };

// Hands out a render's sample indices in increasing order and decides when the render pauses to write a
// checkpoint and when it ends: at its last sample, when a stop signal came (checkpoint/stop_signals.h), or when the
// next batch would end past the time limit. A paused or ended render holds exactly the indices handed out before.
class SampleDispenser {
 public:
  using Clock = std::chrono::steady_clock;
  enum class Pause { None, Checkpoint, End };

  // Indices [first, end); the time limit counts from `jobStart`.
  SampleDispenser(uint32_t first, uint32_t end, const RenderControl& control, Clock::time_point jobStart);

  // Whether to pause now rather than hand out a batch expected to take `batchSeconds`.
  Pause pause(double batchSeconds);
  // The first of the next `count` indices (fewer at the end: see remaining()), now handed out.
  uint32_t take(uint32_t count);
  void checkpointWritten() { lastCheckpoint_ = Clock::now(); }

  uint32_t next() const { return next_; }
  uint32_t remaining() const { return end_ - next_; }
  RenderEnd end() const { return ending_; }

 private:
  uint32_t next_, end_;
  RenderControl control_;
  Clock::time_point jobStart_, lastCheckpoint_;
  RenderEnd ending_ = RenderEnd::Complete;
};

}  // namespace candela
