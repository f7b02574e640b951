#include "app/distributed/distributed_schedule.h"

#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include "app/checkpoint/stop_signals.h"
#include "app/distributed/film_reduction.h"
#include "app/distributed/mpi_session.h"
#include "app/progress.h"

namespace candela {

namespace {

constexpr int kRequestTag = 101, kAssignmentTag = 102;

// A worker's request: what it has done and how fast, and whether it was asked to stop.
struct Request {
  uint32_t samplesDone = 0;
  uint32_t stopSignal = 0;
  double secondsPerSample = 0.0;
};

// Rank 0's answer: an Assignment, with the pause's completed index in `first` and its RenderEnd in `count`.
struct Answer {
  uint32_t kind = 0, first = 0, count = 0;
};

// A batch should keep a rank busy about this long: long against a message, short against a checkpoint interval
// and the end's imbalance, and at least two of rank 0's samples, so that rank 0 answers the next request before
// the batch ends.
constexpr double kBatchSeconds = 1.0;

class CoordinatorSchedule final : public SampleSchedule {
 public:
  CoordinatorSchedule(const SampleDispenser& dispenser, int ranks, bool showProgress, double timeoutSeconds)
      : dispenser_(dispenser),
        workers_(size_t(ranks - 1)),
        first_(dispenser.next()),
        showProgress_(showProgress),
        timeout_(timeoutSeconds),
        progress_("rendering on " + std::to_string(ranks) + " ranks", dispenser.remaining()) {}

  Assignment next(double secondsPerSample) override {
    secondsPerSample_ = secondsPerSample;
    answerRequests();
    if (pause_ == SampleDispenser::Pause::None) pause_ = dispenser_.pause(secondsPerSample);
    if (pause_ == SampleDispenser::Pause::None) return {Assignment::Kind::Samples, dispenser_.take(1), 1};
    // Before a checkpoint, rank 0 goes on rendering while the others finish their batches; the samples stay a
    // prefix of the indices, as rank 0's own are done when it stops. An end waits idle: it is due now.
    if (pause_ == SampleDispenser::Pause::Checkpoint && dispenser_.remaining() > 0 && !allPaused())
      return {Assignment::Kind::Samples, dispenser_.take(1), 1};
    // Every worker learns of the pause at its next request, after its batches.
    const auto start = std::chrono::steady_clock::now();
    while (!allPaused()) {
      if (!answerRequests()) std::this_thread::sleep_for(std::chrono::microseconds(500));
      if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > timeout_)
        throw std::runtime_error(silentRanks() + " did not finish the batches within " + std::to_string(int(timeout_)) +
                                 " s (--rank-timeout)");
    }
    return {pause_ == SampleDispenser::Pause::End ? Assignment::Kind::End : Assignment::Kind::Checkpoint};
  }

  void sampleDone() override {
    ++ownDone_;
    answerRequests();
    if (showProgress_) progress_.update(samplesDone());
  }

  bool combine(Backend& backend, FrameStats& stats) override {
    FilmSums film = backend.readFilm();
    const double seconds = reduceFilm(film, stats, timeout_);
    backend.loadFilm(film);
    if (pause_ == SampleDispenser::Pause::End && showProgress_) {
      progress_.update(dispenser_.next() - first_);
      progress_.finish();
      // What the scaling model of docs/performance.md needs: the time to add up the films.
      std::fprintf(stderr,
                   "films of %zu ranks (%.1f MiB each) added up in %.3f s; rank 0 rendered %u of the %u "
                   "samples per pixel\n",
                   workers_.size() + 1, double(film.bytes()) / double(1 << 20), seconds, ownDone_,
                   dispenser_.next() - first_);
    }
    pause_ = SampleDispenser::Pause::None;
    for (Worker& w : workers_) w.paused = false;
    return true;
  }

  uint32_t completed() const override { return dispenser_.next(); }
  void checkpointWritten() override { dispenser_.checkpointWritten(); }
  RenderEnd end() const override { return dispenser_.end(); }

 private:
  struct Worker {
    uint32_t done = 0;
    bool paused = false;  // told of the current pause
  };

  bool allPaused() const {
    return std::all_of(workers_.begin(), workers_.end(), [](const Worker& w) { return w.paused; });
  }

  uint64_t samplesDone() const {
    uint64_t done = ownDone_;
    for (const Worker& w : workers_) done += w.done;
    return done;
  }

  // "rank 3" or "ranks 3, 5".
  std::string silentRanks() const {
    std::string ranks;
    int count = 0;
    for (size_t i = 0; i < workers_.size(); ++i)
      if (!workers_[i].paused) ranks += (count++ ? ", " : "") + std::to_string(i + 1);
    return (count == 1 ? "rank " : "ranks ") + ranks;
  }

  // The samples per pixel of a batch for a rank that takes `secondsPerSample`: about kBatchSeconds' worth, and
  // towards the end no more than its share of a quarter of the rest (guided self-scheduling, halved again as a
  // rank holds two batches: the one it renders and the next), so that the ranks finish together.
  uint32_t batchSize(double secondsPerSample) const {
    const double target = std::max(kBatchSeconds, 2.0 * secondsPerSample_);
    const double byTime = secondsPerSample > 0.0 ? std::floor(target / secondsPerSample) : 1.0;
    const double share = std::ceil(double(dispenser_.remaining()) / (4.0 * double(workers_.size() + 1)));
    return uint32_t(std::clamp(std::min(byTime, share), 1.0, 65536.0));
  }

  // Answers the requests that have arrived; returns whether there were any.
  bool answerRequests() {
    bool any = false;
    for (;;) {
      int arrived = 0;
      MPI_Status status;
      checkMpi(MPI_Iprobe(MPI_ANY_SOURCE, kRequestTag, MPI_COMM_WORLD, &arrived, &status), "waiting for requests");
      if (!arrived) return any;
      any = true;
      Request request;
      checkMpi(MPI_Recv(&request, sizeof request, MPI_BYTE, status.MPI_SOURCE, kRequestTag, MPI_COMM_WORLD,
                        MPI_STATUS_IGNORE),
               "receiving a request");
      Worker& worker = workers_[size_t(status.MPI_SOURCE - 1)];
      worker.done = request.samplesDone;
      if (request.stopSignal != 0) StopOnSignals::forward(int(request.stopSignal));
      const uint32_t count = batchSize(request.secondsPerSample);
      // The rank renders its current batch before this one: the time limit must allow for both.
      if (pause_ == SampleDispenser::Pause::None) pause_ = dispenser_.pause(2.0 * count * request.secondsPerSample);
      Answer answer;
      if (pause_ == SampleDispenser::Pause::None) {
        answer.kind = uint32_t(Assignment::Kind::Samples);
        answer.first = dispenser_.take(count);
        answer.count = dispenser_.next() - answer.first;
      } else {
        answer.kind =
            uint32_t(pause_ == SampleDispenser::Pause::End ? Assignment::Kind::End : Assignment::Kind::Checkpoint);
        answer.first = dispenser_.next();
        answer.count = uint32_t(dispenser_.end());
        worker.paused = true;
      }
      checkMpi(MPI_Send(&answer, sizeof answer, MPI_BYTE, status.MPI_SOURCE, kAssignmentTag, MPI_COMM_WORLD),
               "sending an assignment");
    }
  }

  SampleDispenser dispenser_;
  std::vector<Worker> workers_;
  SampleDispenser::Pause pause_ = SampleDispenser::Pause::None;
  uint32_t first_;
  bool showProgress_;
  double timeout_;
  double secondsPerSample_ = 0.0;
  uint32_t ownDone_ = 0;
  ProgressReporter progress_;
};

class WorkerSchedule final : public SampleSchedule {
 public:
  explicit WorkerSchedule(double timeoutSeconds) : timeout_(timeoutSeconds) {}

  Assignment next(double secondsPerSample) override {
    secondsPerSample_ = secondsPerSample;
    if (!asked_) ask();
    waitPolitely(reply_, timeout_, "waiting for rank 0");
    asked_ = false;
    const Assignment::Kind kind = Assignment::Kind(answer_.kind);
    if (kind == Assignment::Kind::Samples) {
      const Assignment batch{kind, answer_.first, answer_.count};
      ask();  // the next batch's answer arrives while this one renders
      return batch;
    }
    completed_ = answer_.first;
    end_ = RenderEnd(answer_.count);
    return {kind};
  }

  void sampleDone() override { ++done_; }

  bool combine(Backend& backend, FrameStats& stats) override {
    FilmSums film = backend.readFilm();
    reduceFilm(film, stats, timeout_);
    // Rank 0 holds these samples now; the film starts again for the next ones.
    backend.loadFilm(FilmSums::zero(film.width, film.height, film.hasAovs()));
    return false;
  }

  uint32_t completed() const override { return completed_; }
  void checkpointWritten() override {}
  RenderEnd end() const override { return end_; }

 private:
  void ask() {
    request_ = {done_, uint32_t(StopOnSignals::requested()), secondsPerSample_};
    checkMpi(MPI_Irecv(&answer_, sizeof answer_, MPI_BYTE, 0, kAssignmentTag, MPI_COMM_WORLD, &reply_),
             "asking rank 0 for samples");
    MPI_Request sent;
    checkMpi(MPI_Isend(&request_, sizeof request_, MPI_BYTE, 0, kRequestTag, MPI_COMM_WORLD, &sent),
             "asking rank 0 for samples");
    waitPolitely(sent, timeout_, "asking rank 0 for samples");
    asked_ = true;
  }

  double timeout_;
  double secondsPerSample_ = 0.0;
  Request request_;
  Answer answer_;
  MPI_Request reply_ = MPI_REQUEST_NULL;
  bool asked_ = false;
  uint32_t done_ = 0, completed_ = 0;
  RenderEnd end_ = RenderEnd::Complete;
};

}  // namespace

std::unique_ptr<SampleSchedule> makeCoordinatorSchedule(const SampleDispenser& dispenser, int ranks, bool showProgress,
                                                        double timeoutSeconds) {
  return std::make_unique<CoordinatorSchedule>(dispenser, ranks, showProgress, timeoutSeconds);
}

std::unique_ptr<SampleSchedule> makeWorkerSchedule(double timeoutSeconds) {
  return std::make_unique<WorkerSchedule>(timeoutSeconds);
}

}  // namespace candela
