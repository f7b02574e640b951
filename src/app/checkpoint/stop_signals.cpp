#include "app/checkpoint/stop_signals.h"

#include <csignal>

#include "core/atomic_file.h"

namespace candela {

namespace {

volatile std::sig_atomic_t stopSignal = 0;
struct sigaction previousInt, previousTerm;

void requestStop(int signal) {
  stopSignal = signal;
  // The next one ends the process the way it would have ended before.
  ::sigaction(signal, signal == SIGINT ? &previousInt : &previousTerm, nullptr);
}

}  // namespace

StopOnSignals::StopOnSignals() {
  installTemporaryRemovalOnSignals();
  stopSignal = 0;
  struct sigaction action {};
  action.sa_handler = &requestStop;
  sigemptyset(&action.sa_mask);
  ::sigaction(SIGINT, &action, &previousInt);
  ::sigaction(SIGTERM, &action, &previousTerm);
}

StopOnSignals::~StopOnSignals() {
  ::sigaction(SIGINT, &previousInt, nullptr);
  ::sigaction(SIGTERM, &previousTerm, nullptr);
}

int StopOnSignals::requested() { return stopSignal; }

void StopOnSignals::forward(int signal) {
  if (stopSignal == 0) stopSignal = signal;
}

void StopOnSignals::endWithRequestedSignal() {
  const int signal = stopSignal;
  if (signal == 0) return;
  ::sigaction(signal, signal == SIGINT ? &previousInt : &previousTerm, nullptr);
  ::raise(signal);
}

const char* StopOnSignals::signalName(int signal) { return signal == SIGINT ? "SIGINT" : "SIGTERM"; }

}  // namespace candela
