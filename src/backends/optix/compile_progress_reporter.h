#pragma once
// Tells a ProgramCompileListener how a compile goes, once it has lasted longer than a moment, from a thread of its
// own: the thread doing the compile's work (taking part in OptiX's tasks, then linking pipelines) need not stop
// to report, and a cached start, over within the moment, reports nothing.
#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>

#include "backends/optix/compile_progress.h"

namespace candela::optix {

class CompileProgressReporter {
 public:
  // `about` names the GPU and the cache; `tasks` reads the compile's task counts (on the reporter's thread). An
  // empty listener makes a reporter that does nothing.
  CompileProgressReporter(ProgramCompileListener listener, ProgramCompileProgress about,
                          std::function<CompileTaskCounts()> tasks);
  // Reports Failed when the compile was reported and finish() was not called: an exception left it.
  ~CompileProgressReporter();
  CompileProgressReporter(const CompileProgressReporter&) = delete;
  CompileProgressReporter& operator=(const CompileProgressReporter&) = delete;

  // The compile is over: reports Finished, where it was reported at all.
  void finish();

 private:
  using Clock = std::chrono::steady_clock;
  void run();
  // Stops the thread, then sends the last report (`last`) where there were others.
  void stop(ProgramCompileProgress::Stage last);
  void report(ProgramCompileProgress::Stage stage);

  ProgramCompileListener listener_;
  ProgramCompileProgress progress_;
  std::function<CompileTaskCounts()> tasks_;
  Clock::time_point start_ = Clock::now();
  bool reported_ = false;  // written by the thread, read after it has been joined
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace candela::optix
