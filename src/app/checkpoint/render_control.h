#pragma once
#include <chrono>
#include <string>

namespace candela {

// How a long render saves itself and when it stops early (--checkpoint, --checkpoint-every, --time-limit,
// --resume). All off by default: a render then runs to its last sample, as it always did.
struct RenderControl {
  std::string checkpointPath;           // written periodically, when the render stops, and at its end
  double checkpointEverySeconds = 0.0;  // 0: only when the render stops or ends
  double timeLimitSeconds = 0.0;        // from the start of the job; 0: none
  std::string resumePath;               // a checkpoint to continue from
  // Where the time limit counts from: the job's start (before the scene loads); unset, the render's start.
  std::chrono::steady_clock::time_point timeLimitFrom{};

  // Whether SIGINT and SIGTERM stop the render at a sample boundary, to write the checkpoint.
  bool stopsOnSignals() const { return !checkpointPath.empty(); }
};

}  // namespace candela
