#pragma once
#include "app/progress.h"
#include "app/schedule/sample_schedule.h"

namespace candela {

// One process renders every sample index, one sample per pixel at a time, with progress on stderr.
class LocalSchedule final : public SampleSchedule {
 public:
  LocalSchedule(const SampleDispenser& dispenser, bool showProgress);

  Assignment next(double secondsPerSample) override;
  void sampleDone() override;
  bool combine(Backend&, FrameStats&) override { return true; }
  uint32_t completed() const override { return dispenser_.next(); }
  void checkpointWritten() override { dispenser_.checkpointWritten(); }
  RenderEnd end() const override { return dispenser_.end(); }

 private:
  SampleDispenser dispenser_;
  uint32_t first_;
  bool showProgress_;
  ProgressReporter progress_;
};

}  // namespace candela
