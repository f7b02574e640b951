#pragma once
#include <chrono>
#include <cstdint>
#include <string>

namespace candela {

// Reports progress of a long render on stderr: a redrawn bar with ETA on a terminal, a plain line every few
// seconds otherwise (logs, CI).
class ProgressReporter {
 public:
  ProgressReporter(std::string label, uint64_t total);
  void update(uint64_t done);
  void finish();

 private:
  using Clock = std::chrono::steady_clock;
  std::string label_;
  uint64_t total_;
  bool terminal_;
  Clock::time_point start_;
  Clock::time_point lastPrint_;
};

std::string formatSeconds(double seconds);

}  // namespace candela
