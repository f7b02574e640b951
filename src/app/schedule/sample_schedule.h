#pragma once
#include <cstdint>

#include "app/schedule/sample_dispenser.h"
#include "backends/backend.h"

namespace candela {

// What a process does next in a render.
struct Assignment {
  enum class Kind {
    Samples,     // render the sample indices [first, first + count) into the film
    Checkpoint,  // add up the films and write the checkpoint, then ask again
    End,         // add up the films: the render is over
  } kind = Kind::End;
  uint32_t first = 0, count = 0;
};

// Where a process's sample indices come from, and how the films of the processes of a render become one: a
// single process renders them all (LocalSchedule); the ranks of a distributed render share them
// (distributed/distributed_schedule.h).
class SampleSchedule {
 public:
  virtual ~SampleSchedule() = default;
  // The next assignment; `secondsPerSample` is how long this process took per sample so far (0 before the first).
  virtual Assignment next(double secondsPerSample) = 0;
  // After each sample of an assignment (progress, messages).
  virtual void sampleDone() {}
  // At Checkpoint and End, on every process: leaves the sum of all the processes' films and stats in the
  // backend and `stats` of the process that writes the checkpoint and the image, and returns whether this
  // process is that one. The film then holds the sample indices [0, completed()).
  virtual bool combine(Backend& backend, FrameStats& stats) = 0;
  virtual uint32_t completed() const = 0;
  virtual void checkpointWritten() = 0;
  virtual RenderEnd end() const = 0;
};

}  // namespace candela
