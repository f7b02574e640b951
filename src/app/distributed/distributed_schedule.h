#pragma once
#include <memory>

#include "app/schedule/sample_schedule.h"

namespace candela {

// The schedules of a distributed render's ranks. Rank 0 hands out batches of sample indices from its dispenser
// on request, so that a faster rank takes more, and renders its own share one sample at a time between the
// requests; the other ranks ask for their next batch as they start one, so that its answer is there when they
// finish. At a checkpoint or the end, rank 0 answers every request with the pause: then every handed-out batch
// is rendered, and all ranks add up their films onto rank 0 (film_reduction.h), which writes. Rank 0 shows the
// progress of all ranks.
//
// A rank that has not finished its batches when the others have paused, within `timeoutSeconds` (a stopped
// process, a hung GPU, a dead node), is given up: the ranks that paused send rank 0 their films and stop, rank 0
// renders the lost rank's batches since the last checkpoint again and the rest of the render alone, with a
// warning, and sets `ranksLost` (the lost rank cannot end MPI with the others); each rank let go sets its
// `released`. A coordinator's schedule made once `ranksLost` is set (the next frame of a sequence) renders alone
// from its start, answering only a lost rank that comes back (with the end of its work).
std::unique_ptr<SampleSchedule> makeCoordinatorSchedule(const SampleDispenser& dispenser, int ranks, bool showProgress,
                                                        double timeoutSeconds, bool& ranksLost);
std::unique_ptr<SampleSchedule> makeWorkerSchedule(double timeoutSeconds, bool& released);

}  // namespace candela
