#pragma once
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>

#include "backends/optix/compile_progress.h"

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

// The lines of the GPU backend's compile of its programs (backends/optix/compile_progress.h): the compile began,
// how far it is, and how it ended (Finished or Failed).
std::string compileStartLine(const ProgramCompileProgress& progress);
std::string compileStatusLine(const ProgramCompileProgress& progress);
std::string compileEndLine(const ProgramCompileProgress& progress);

// Prints those lines as ProgressReporter prints a render's: the status redrawn on one line on a terminal, a plain
// line every few seconds otherwise.
class CompileProgressPrinter {
 public:
  CompileProgressPrinter(std::FILE* out, bool terminal);
  void operator()(const ProgramCompileProgress& progress);

 private:
  std::FILE* out_;
  bool terminal_;
  double lastStatusSeconds_ = 0.0;  // the compile's time at the last status line
  size_t statusWidth_ = 0;          // of the status line on the terminal, which the next one overwrites
};

// A CompileProgressPrinter on stderr, for createBackend (app/backend_factory.h).
ProgramCompileListener compileProgressOnStderr();

}  // namespace candela
