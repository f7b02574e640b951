#include "app/distributed/distributed_render.h"

#include <cstdio>
#include <optional>

#include "app/checkpoint/stop_signals.h"
#include "app/distributed/mpi_team.h"
#include "io/load_diagnostics.h"

namespace candela {

namespace {

// Runs `render` on this rank with the ranks of MPI_COMM_WORLD as `job`'s team. Returns nothing when it returned,
// and the exit status when it failed: on a failure every rank agreed on, rank 0's one line and 1; any other
// failure ends the whole job, as the other ranks may wait for this one in a collective.
std::optional<int> renderAsTeam(RenderJob job, const MpiSession& session, MpiTeam& team,
                                const std::function<void(const RenderJob&)>& render) {
  if (session.size() > 1) job.team = &team;
  try {
    render(job);
    return std::nullopt;
  } catch (const AgreedFailure& e) {
    if (*e.what()) std::fprintf(stderr, "candela: %s\n", printableText(e.what()).c_str());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "candela: rank %d of %d: %s\n", session.rank(), session.size(),
                 printableText(e.what()).c_str());
    std::fflush(stderr);
    session.abort(1);
  }
}

}  // namespace

int runDistributedRender(RenderJob job, double rankTimeoutSeconds, const std::function<void()>& checkOutputs,
                         const std::function<int(const RenderOutcome&)>& writeOutputs) {
  MpiSession session;
  MpiTeam team(session, rankTimeoutSeconds);
  RenderOutcome outcome;
  const std::optional<int> failed = renderAsTeam(job, session, team, [&](const RenderJob& teamJob) {
    std::exception_ptr failure;
    try {
      if (team.writes()) checkOutputs();
    } catch (...) {
      failure = std::current_exception();
    }
    team.agree(failure);
    outcome = runRenderJob(teamJob, /*showProgress=*/team.writes());
  });
  if (failed) return *failed;
  // From here on no rank waits for another.
  if (!outcome.writes) return outcome.end == RenderEnd::Signal ? 128 + StopOnSignals::requested() : 0;
  int status = 1;
  try {
    status = writeOutputs(outcome);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "candela: %s\n", printableText(e.what()).c_str());
  }
  // A rank given up for lost would hold MPI's end up for ever: the job ends here, with the outputs written.
  if (team.ranksLost()) {
    std::fflush(stdout);
    std::fflush(stderr);
    session.abort(status);
  }
  return status;
}

int runDistributedSequence(RenderJob job, double rankTimeoutSeconds,
                           const std::function<int(const RenderJob&)>& renderSequence) {
  MpiSession session;
  MpiTeam team(session, rankTimeoutSeconds);
  int status = 0;
  const std::optional<int> failed =
      renderAsTeam(job, session, team, [&](const RenderJob& teamJob) { status = renderSequence(teamJob); });
  if (failed) status = *failed;
  // As for one image: a rank given up for lost would hold MPI's end up for ever.
  if (team.ranksLost()) {
    std::fflush(stdout);
    std::fflush(stderr);
    session.abort(status);
  }
  return status;
}

}  // namespace candela
