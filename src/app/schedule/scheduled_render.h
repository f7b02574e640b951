#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "app/schedule/sample_schedule.h"
#include "io/images/image_io.h"

namespace candela {

// Where checkpoints go and what they say about the render (checkpoint/checkpoint_file.h).
struct CheckpointTarget {
  std::string path;  // empty: none are written
  ExrAttributes identity;
  uint32_t samplesPerPixel = 0;
};

struct ScheduledRenderResult {
  bool writes = true;    // this process holds the whole film: it writes the image
  uint32_t samples = 0;  // sample indices [0, samples) in the film
  RenderEnd end = RenderEnd::Complete;
  bool checkpointFailed = false;  // the last checkpoint could not be written (a warning said why)
  FrameStats stats;
  std::vector<double> frameMilliseconds, deviceFrameMilliseconds;  // this process's launches
  std::vector<std::vector<double>> perDeviceFrameMilliseconds;     // [launch][device], on several devices
};

// Runs `schedule`'s assignments on `backend` (its scene, settings and camera set, its film holding any resumed
// samples): renders their sample indices one sample per pixel per launch, and writes the checkpoints. `render`
// runs one launch of one sample per pixel. A checkpoint that cannot be written (a full disk, a quota) is a
// warning: the render goes on, and its image is written at the end.
ScheduledRenderResult renderScheduled(Backend& backend, SampleSchedule& schedule, const CheckpointTarget& checkpoint,
                                      const std::function<FrameStats()>& render);

}  // namespace candela
