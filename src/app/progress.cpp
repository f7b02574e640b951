#include "app/progress.h"

#include <unistd.h>

#include <cstdio>

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

}  // namespace candela
