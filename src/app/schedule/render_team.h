#pragma once
#include <exception>
#include <memory>
#include <stdexcept>

#include "app/schedule/sample_schedule.h"
#include "io/images/image_io.h"

namespace candela {

// A failure every process of a team learnt of together (RenderTeam::agree): the writer's carries the one line to
// print, the others' is empty. Each exits with status 1.
class AgreedFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The processes that render one image together (distributed/mpi_team.h); a render without one is a single
// process's. Every process loads the scene and renders a share of the sample indices; one of them writes.
class RenderTeam {
 public:
  virtual ~RenderTeam() = default;
  // Whether this process writes the image and checkpoints, and reads the checkpoint it resumes from.
  virtual bool writes() const = 0;
  // Which of its node's GPUs this process takes (its rank among the processes on its node).
  virtual int localIndex() const = 0;
  // Every process calls it after a step that may fail on some of them, with its failure or null. Returns when
  // none failed; otherwise every process throws AgreedFailure, the writer's with the first failing process's
  // message and which process it was.
  virtual void agree(std::exception_ptr failure) = 0;
  // Every process calls it before rendering, with its render's identity (checkpoint/render_identity.h:
  // teamIdentity). Returns when every process has the writer's; otherwise every process throws AgreedFailure, the
  // writer's naming the first process that differs and the first difference, so that no process adds samples of
  // another scene or settings to the image, or waits for a film of another size.
  virtual void checkSameRender(const ExrAttributes& identity) = 0;
  // The schedule of this process; the writer's hands out `dispenser`'s indices to all.
  virtual std::unique_ptr<SampleSchedule> schedule(const SampleDispenser& dispenser, bool showProgress) = 0;
  // Whether the writer has let this process go: it was given up for lost, or the writer took its film when
  // another process stopped answering and renders the rest alone (distributed/distributed_schedule.h). A process
  // that was let go renders no further frame of a sequence.
  virtual bool released() const = 0;
};

// Runs `step`, a start-up step that may fail on some processes of `team`, and returns its result; with a team,
// every process learns whether it failed anywhere (RenderTeam::agree). Without one it is just `step()`.
template <class Step>
auto agreedStep(RenderTeam* team, const Step& step) {
  if (!team) return step();
  try {
    auto result = step();
    team->agree(nullptr);
    return result;
  } catch (const AgreedFailure&) {
    throw;
  } catch (...) {
    team->agree(std::current_exception());
    throw std::logic_error("RenderTeam::agree returned after a failure");
  }
}

}  // namespace candela
