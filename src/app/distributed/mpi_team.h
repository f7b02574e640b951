#pragma once
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
  const MpiSession& session_;
  double timeout_;
  bool ranksLost_ = false;    // on rank 0
  bool released_ = false;     // on the other ranks
  bool warnedAlone_ = false;  // rank 0 said that it renders the remaining frames alone
};

}  // namespace candela
