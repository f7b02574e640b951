#include "app/progress.h"

#include <unistd.h>

#include <cstdio>
#include <memory>

namespace candela {

namespace {
constexpr int kBarWidth = 30;
constexpr double kTerminalInterval = 0.1, kLogInterval = 5.0;
}  // namespace

std::string formatSeconds(double seconds) {
  char buffer[32];
  if (seconds < 60.0)
    std::snprintf(buffer, sizeof buffer, "%.1fs", seconds);
  else
    std::snprintf(buffer, sizeof buffer, "%dm%02ds", int(seconds) / 60, int(seconds) % 60);
  return buffer;
}

ProgressReporter::ProgressReporter(std::string label, uint64_t total)
    : label_(std::move(label)),
      total_(total),
      terminal_(isatty(STDERR_FILENO) != 0),
      start_(Clock::now()),
      lastPrint_(start_) {}

void ProgressReporter::update(uint64_t done) {
  Clock::time_point now = Clock::now();
  double sinceLast = std::chrono::duration<double>(now - lastPrint_).count();
  if (sinceLast < (terminal_ ? kTerminalInterval : kLogInterval) && done < total_) return;
  lastPrint_ = now;
  double elapsed = std::chrono::duration<double>(now - start_).count();
  double fraction = total_ ? double(done) / double(total_) : 1.0;
  double eta = fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
  if (terminal_) {
    int filled = int(fraction * kBarWidth);
    std::string bar(size_t(filled), '#');
    bar.resize(kBarWidth, '.');
    std::fprintf(stderr, "\r%s [%s] %3d%% %llu/%llu  elapsed %s  eta %s   ", label_.c_str(), bar.c_str(),
                 int(fraction * 100.0), (unsigned long long)done, (unsigned long long)total_,
                 formatSeconds(elapsed).c_str(), formatSeconds(eta).c_str());
  } else {
    std::fprintf(stderr, "%s: %llu/%llu (%d%%), elapsed %s, eta %s\n", label_.c_str(), (unsigned long long)done,
                 (unsigned long long)total_, int(fraction * 100.0), formatSeconds(elapsed).c_str(),
                 formatSeconds(eta).c_str());
  }
  std::fflush(stderr);
}

void ProgressReporter::finish() {
  if (terminal_) std::fprintf(stderr, "\n");
}

std::string compileStartLine(const ProgramCompileProgress& progress) {
  const std::string where = progress.cacheDirectory.empty()
                                ? "not cached: every start compiles them"
                                : "first start on this machine; cached in " + progress.cacheDirectory;
  return "optix: compiling the GPU programs for " + progress.gpuName + " (" + where + ")...";
}

std::string compileStatusLine(const ProgramCompileProgress& progress) {
  return "optix: compiling, " + std::to_string(progress.tasks.done) + "/" + std::to_string(progress.tasks.known) +
         " tasks done, " + formatSeconds(progress.seconds);
}

std::string compileEndLine(const ProgramCompileProgress& progress) {
  if (progress.stage == ProgramCompileProgress::Stage::Failed)
    return "optix: compiling the GPU programs failed after " + formatSeconds(progress.seconds);
  return "optix: compiled the GPU programs in " + formatSeconds(progress.seconds) + " (" +
         std::to_string(progress.tasks.known) + " tasks)";
}

CompileProgressPrinter::CompileProgressPrinter(std::FILE* out, bool terminal) : out_(out), terminal_(terminal) {}

void CompileProgressPrinter::operator()(const ProgramCompileProgress& progress) {
  using Stage = ProgramCompileProgress::Stage;
  // On a terminal each line overwrites the status line, padded to cover it.
  auto overwrite = [&](const std::string& line) {
    std::fprintf(out_, "\r%-*s", int(statusWidth_), line.c_str());
    statusWidth_ = line.size();
  };
  switch (progress.stage) {
    case Stage::Started:
      std::fprintf(out_, "%s\n", compileStartLine(progress).c_str());
      lastStatusSeconds_ = progress.seconds;
      break;
    case Stage::Running:
      if (!terminal_ && progress.seconds - lastStatusSeconds_ < kLogInterval) return;  // a terminal's: every one
      lastStatusSeconds_ = progress.seconds;
      if (terminal_)
        overwrite(compileStatusLine(progress));
      else
        std::fprintf(out_, "%s\n", compileStatusLine(progress).c_str());
      break;
    case Stage::Finished:
    case Stage::Failed:
      if (terminal_) {
        overwrite(compileEndLine(progress));
        std::fprintf(out_, "\n");
      } else {
        std::fprintf(out_, "%s\n", compileEndLine(progress).c_str());
      }
      statusWidth_ = 0;
      break;
  }
  std::fflush(out_);
}

ProgramCompileListener compileProgressOnStderr() {
  auto printer = std::make_shared<CompileProgressPrinter>(stderr, isatty(STDERR_FILENO) != 0);
  return [printer](const ProgramCompileProgress& progress) { (*printer)(progress); };
}

}  // namespace candela
