#include "app/checkpoint/stop_signals.h"

#include <csignal>

#include "io/atomic_file.h"

namespace candela {

namespace {

volatile std::sig_atomic_t stopSignal = 0;
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
  if (stopSignal == 0) stopSignal = signal;
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
