#include "app/distributed/distributed_render.h"

#include <cstdio>

#include "app/checkpoint/stop_signals.h"
#include "app/distributed/mpi_team.h"
#include "scene/loaders/load_diagnostics.h"

namespace candela {

int runDistributedRender(RenderJob job, double rankTimeoutSeconds, const std::function<void()>& checkOutputs,
                         const std::function<int(const RenderOutcome&)>& writeOutputs) {
  MpiSession session;
  MpiTeam team(session, rankTimeoutSeconds);
  if (session.size() > 1) job.team = &team;
  RenderOutcome outcome;
  try {
    std::exception_ptr failure;
    try {
      if (team.writes()) checkOutputs();
    } catch (...) {
      failure = std::current_exception();
    }
    team.agree(failure);
    outcome = runRenderJob(job, /*showProgress=*/team.writes());
  } catch (const AgreedFailure& e) {
    if (*e.what()) std::fprintf(stderr, "candela: %s\n", printableText(e.what()).c_str());
    return 1;
  } catch (const std::exception& e) {
    // The other ranks may wait for this one in a collective: end them all.
    std::fprintf(stderr, "candela: rank %d of %d: %s\n", session.rank(), session.size(),
                 printableText(e.what()).c_str());
    std::fflush(stderr);
    session.abort(1);
  }
  // From here on no rank waits for another.
  if (!outcome.writes) return outcome.end == RenderEnd::Signal ? 128 + StopOnSignals::requested() : 0;
  try {
    return writeOutputs(outcome);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "candela: %s\n", printableText(e.what()).c_str());
    return 1;
  }
}

}  // namespace candela
