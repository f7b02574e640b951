#include "app/schedule/local_schedule.h"

namespace candela {

LocalSchedule::LocalSchedule(const SampleDispenser& dispenser, bool showProgress)
    : dispenser_(dispenser),
      first_(dispenser.next()),
      showProgress_(showProgress),
      progress_("rendering", dispenser.remaining()) {}

Assignment LocalSchedule::next(double secondsPerSample) {
  switch (dispenser_.pause(secondsPerSample)) {
    case SampleDispenser::Pause::Checkpoint: return {Assignment::Kind::Checkpoint};
    case SampleDispenser::Pause::End:
      if (showProgress_) progress_.finish();
      return {Assignment::Kind::End};
    case SampleDispenser::Pause::None: break;
  }
  return {Assignment::Kind::Samples, dispenser_.take(1), 1};
}

void LocalSchedule::sampleDone() {
  if (showProgress_) progress_.update(dispenser_.next() - first_);
}

}  // namespace candela
