#pragma once

namespace candela {

// While it lives, the first SIGINT, SIGTERM or SIGUSR1 asks the render to stop at its next sample boundary (so
// that it can write its checkpoint) instead of ending the process; a second one ends the process as before,
// through the handlers that remove uncommitted temporary files (io/atomic_file.h). SIGUSR1 is the one mpirun
// forwards to the ranks (it ends the job on SIGTERM) and the one Slurm's --signal sends before a job's time
// limit. One at a time per process.
class StopOnSignals {
 public:
  StopOnSignals();
  ~StopOnSignals();
  StopOnSignals(const StopOnSignals&) = delete;
  StopOnSignals& operator=(const StopOnSignals&) = delete;

  // The signal that asked to stop, or 0.
  static int requested();
  // Takes a stop request that came to another process of the render as this one's, unless one came here.
  static void forward(int signal);
  // Ends the process with the signal that asked to stop, as it would have ended without this object; returns
  // when none did.
  static void endWithRequestedSignal();
  static const char* signalName(int signal);
};

}  // namespace candela
