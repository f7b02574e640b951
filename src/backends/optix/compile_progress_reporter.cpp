#include "backends/optix/compile_progress_reporter.h"

#include <utility>

namespace candela::optix {

namespace {
constexpr std::chrono::milliseconds kReportInterval{100};
}  // namespace

CompileProgressReporter::CompileProgressReporter(ProgramCompileListener listener, ProgramCompileProgress about,
                                                 std::function<CompileTaskCounts()> tasks)
    : listener_(std::move(listener)), progress_(std::move(about)), tasks_(std::move(tasks)) {
  if (listener_) thread_ = std::thread([this] { run(); });
}

CompileProgressReporter::~CompileProgressReporter() { stop(ProgramCompileProgress::Stage::Failed); }

void CompileProgressReporter::finish() { stop(ProgramCompileProgress::Stage::Finished); }

void CompileProgressReporter::run() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (!wake_.wait_for(lock, kReportInterval, [this] { return stopping_; })) {
    if (std::chrono::duration<double>(Clock::now() - start_).count() < kProgramCompileQuietSeconds) continue;
    report(reported_ ? ProgramCompileProgress::Stage::Running : ProgramCompileProgress::Stage::Started);
    reported_ = true;
  }
}

void CompileProgressReporter::stop(ProgramCompileProgress::Stage last) {
  if (!thread_.joinable()) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_one();
  thread_.join();
  if (reported_) report(last);
}

void CompileProgressReporter::report(ProgramCompileProgress::Stage stage) {
  progress_.stage = stage;
  progress_.tasks = tasks_();
  progress_.seconds = std::chrono::duration<double>(Clock::now() - start_).count();
  listener_(progress_);
}

}  // namespace candela::optix
