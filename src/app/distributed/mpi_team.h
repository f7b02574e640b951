#pragma once
#include <cstdint>
#include <string>

#include "app/distributed/mpi_session.h"
#include "app/schedule/render_team.h"

namespace candela {

// The ranks of MPI_COMM_WORLD as a render team: rank 0 writes; each rank takes the GPU of its rank on its node.
class MpiTeam final : public RenderTeam {
 public:
  // `timeoutSeconds`: how long a rank waits for another before it ends the job (--rank-timeout).
  MpiTeam(const MpiSession& session, double timeoutSeconds) : session_(session), timeout_(timeoutSeconds) {}

  bool writes() const override { return session_.rank() == 0; }
  int localIndex() const override { return session_.localRank(); }
  void agree(std::exception_ptr failure) override;
  void checkSameRender(const ExrAttributes& identity) override;
  std::unique_ptr<SampleSchedule> schedule(const SampleDispenser& dispenser, bool showProgress) override;
  bool released() const override { return released_; }
  // Whether rank 0 gave up a rank that stopped answering (distributed_schedule.h) and rendered on without it.
  // From then on rank 0 is the team: it agrees with itself, and renders every later frame of a sequence alone.
  bool ranksLost() const { return ranksLost_; }

 private:
  // Waits for a collective step of the team (`what`, for a timeout's message). Until the team has rendered, a
  // rank that does not come within the timeout ends the job (the error is thrown). Between the frames of a
  // sequence, rank 0 instead gives the others up, as it does for a rank that stops within a frame: it tells them
  // so, warns, and renders the remaining frames alone; a rank it lets go stops waiting. Returns whether the step
  // completed; when not, ranksLost_ is set (on rank 0) or released_ (on the others), and the step's request is
  // left pending: its buffers are members, which outlive it.
  bool awaitTeam(MPI_Request& request, const char* what);
  void goOnAlone();
  bool releaseArrived();

  const MpiSession& session_;
  double timeout_;
  bool ranksLost_ = false;    // on rank 0
  bool released_ = false;     // on the other ranks
  bool warnedAlone_ = false;  // rank 0 said that it renders the remaining frames alone
  bool rendered_ = false;     // the team has made a schedule: a frame was rendered or is being rendered
  // The buffers of the collective steps (checkSameRender, agree).
  uint64_t identityLength_ = 0;
  std::string writersIdentity_;
  int failingRank_ = 0, firstFailingRank_ = 0;
};

}  // namespace candela
