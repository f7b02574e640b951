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

// One rank's part of an image sequence (`candela render --frames A:B`, or one --time) under an MPI launcher:
// `renderSequence` (runAnimatedRender) runs on every rank with the ranks as the job's team, and returns the exit
// status. Failures end the job as runDistributedRender's do; an image rank 0 cannot write ends it too.
//
// The ranks share every frame's samples, frame after frame, rather than take whole frames: a sequence of fewer
// frames than ranks (a short shot, a single --time) keeps every rank busy, and a fast rank takes more batches of
// each frame, so an uneven rank (a GPU beside CPUs, a busy node) delays a frame by at most a batch (about a
// second), where with whole frames the last frame on the slowest rank would hold up the sequence's end. The cost
// is a film reduction onto rank 0 per frame, with the ranks waiting for rank 0 to write each image: small against
// frames of many samples (docs/performance.md's model: 0.12 s for a 1080p film at 1 GB/s), but a sequence of many
// quick frames renders faster as separate jobs, one per rank, each on a range of frames. Rank 0 writes every
// frame because the reduction leaves the only whole film there.
int runDistributedSequence(RenderJob job, double rankTimeoutSeconds,
                           const std::function<int(const RenderJob&)>& renderSequence);

}  // namespace candela
