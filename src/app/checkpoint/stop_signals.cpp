#include "app/checkpoint/stop_signals.h"

#include <atomic>
#include <csignal>

#include "io/atomic_file.h"

namespace candela {

namespace {

// Atomic, not a volatile sig_atomic_t: a process's signal may be handled on any of its threads that does not block
// it (Linux prefers the main thread, but not always), a TBB worker as well as the thread that renders and reads
// it; for a plain variable that is a data race.
std::atomic<int> stopSignal{0};
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler sets it");
constexpr int kStopSignals[] = {SIGINT, SIGTERM, SIGUSR1};
struct sigaction previous[3];

struct sigaction* previousOf(int signal) {
  for (int i = 0; i < 3; ++i)
    if (kStopSignals[i] == signal) return &previous[i];
  return nullptr;
}

void requestStop(int signal) {
  stopSignal = signal;
  // The next one ends the process the way it would have ended before.
  ::sigaction(signal, previousOf(signal), nullptr);
}

}  // namespace

StopOnSignals::StopOnSignals() {
  installTemporaryRemovalOnSignals();
  stopSignal = 0;
  struct sigaction action {};
  action.sa_handler = &requestStop;
  sigemptyset(&action.sa_mask);
  for (int i = 0; i < 3; ++i) ::sigaction(kStopSignals[i], &action, &previous[i]);
}

StopOnSignals::~StopOnSignals() {
  for (int i = 0; i < 3; ++i) ::sigaction(kStopSignals[i], &previous[i], nullptr);
}

int StopOnSignals::requested() { return stopSignal; }

void StopOnSignals::forward(int signal) {
  int none = 0;
  stopSignal.compare_exchange_strong(none, signal);  // a signal that came here meanwhile stays
}

void StopOnSignals::endWithRequestedSignal() {
  const int signal = stopSignal;
  if (signal == 0) return;
  ::sigaction(signal, previousOf(signal), nullptr);
  ::raise(signal);
}

const char* StopOnSignals::signalName(int signal) {
  return signal == SIGINT ? "SIGINT" : signal == SIGTERM ? "SIGTERM" : "SIGUSR1";
}

}  // namespace candela
