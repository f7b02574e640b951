#pragma once
#include <functional>

#include "app/render_job.h"

namespace candela {

// One rank's part of `candela render` under an MPI launcher: every rank loads the scene and renders a share of
// the sample indices (distributed_schedule.h); rank 0 checks the outputs first (`checkOutputs`), shows the
// progress and, with all films added up, writes (`writeOutputs`, which returns the exit status). A failure in the
// start-up of any rank (scene, checkpoint, backend, outputs) is one line from rank 0 and exit status 1 on all; a
// failure later ends the whole job (MPI_Abort) rather than leave the other ranks waiting. A rank that hears
// nothing from the others for `rankTimeoutSeconds` ends the job too. Returns this rank's exit status.
int runDistributedRender(RenderJob job, double rankTimeoutSeconds, const std::function<void()>& checkOutputs,
                         const std::function<int(const RenderOutcome&)>& writeOutputs);

}  // namespace candela
