#include "app/schedule/scheduled_render.h"

#include <chrono>
#include <cstdio>
#include <stdexcept>

#include "app/checkpoint/checkpoint_file.h"
#include "io/load_diagnostics.h"

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
    if (result.writes && !checkpoint.path.empty()) {
      try {
        writeCheckpoint(checkpoint.path,
                        {checkpoint.identity, result.samples, checkpoint.samplesPerPixel, backend.readFilm()});
        result.checkpointFailed = false;
      } catch (const std::invalid_argument&) {
        throw;
      } catch (const std::exception& e) {  // WriteError, or OpenEXR's own
        std::fprintf(stderr, "candela: warning: no checkpoint after %u samples per pixel: %s; the render goes on\n",
                     result.samples, printableText(e.what()).c_str());
        result.checkpointFailed = true;
      }
    }
    schedule.checkpointWritten();
    if (a.kind == Assignment::Kind::End) {
      result.stats = combined;
      result.end = schedule.end();
      return result;
    }
  }
}

}  // namespace candela
