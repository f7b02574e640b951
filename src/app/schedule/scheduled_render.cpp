#include "app/schedule/scheduled_render.h"

#include <chrono>

#include "app/checkpoint/checkpoint_file.h"

namespace candela {

ScheduledRenderResult renderScheduled(Backend& backend, SampleSchedule& schedule, const CheckpointTarget& checkpoint,
                                      const std::function<FrameStats()>& render) {
  using Clock = std::chrono::steady_clock;
  ScheduledRenderResult result;
  double renderSeconds = 0.0;
  uint32_t rendered = 0;
  for (;;) {
    const Assignment a = schedule.next(rendered > 0 ? renderSeconds / rendered : 0.0);
    if (a.kind == Assignment::Kind::Samples) {
      backend.setNextSampleIndex(a.first);
      for (uint32_t i = 0; i < a.count; ++i) {
        const auto start = Clock::now();
        const FrameStats frame = render();
        const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
        renderSeconds += ms / 1000.0;
        ++rendered;
        result.frameMilliseconds.push_back(ms);
        if (frame.deviceMilliseconds > 0.0) result.deviceFrameMilliseconds.push_back(frame.deviceMilliseconds);
        if (!frame.perDeviceMilliseconds.empty())
          result.perDeviceFrameMilliseconds.push_back(frame.perDeviceMilliseconds);
        result.stats.rays += frame.rays;
        result.stats.invalidSamples += frame.invalidSamples;
        schedule.sampleDone();
      }
      continue;
    }
    FrameStats combined = result.stats;
    result.writes = schedule.combine(backend, combined);
    result.samples = schedule.completed();
    if (result.writes && !checkpoint.path.empty())
      writeCheckpoint(checkpoint.path,
                      {checkpoint.identity, result.samples, checkpoint.samplesPerPixel, backend.readFilm()});
    schedule.checkpointWritten();
    if (a.kind == Assignment::Kind::End) {
      result.stats = combined;
      result.end = schedule.end();
      return result;
    }
  }
}

}  // namespace candela
