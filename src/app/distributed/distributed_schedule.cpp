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

constexpr int kRequestTag = 101, kAssignmentTag = 102, kCombineTag = 105, kReadyTag = 107;

// How a rank that was told of a pause combines its film (rank 0 says so once the rank is ready, in combine(), with
// its batches rendered and its film read): with all the others (reduceFilm), or, once a rank has stopped
// answering, sent to rank 0 alone, after which this rank is done; or not at all (it was given up for lost, and its
// samples are rendered again).
enum class Combine : uint32_t { Reduce, SendAndStop, DiscardAndStop };

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

void tellCombine(int rank, Combine how, double timeoutSeconds) {
  const uint32_t value = uint32_t(how);
  MPI_Request request;
  checkMpi(MPI_Isend(&value, 1, MPI_UINT32_T, rank, kCombineTag, MPI_COMM_WORLD, &request), "starting to add up");
  waitPolitely(request, timeoutSeconds, "starting to add up the films");
}

class CoordinatorSchedule final : public SampleSchedule {
 public:
  CoordinatorSchedule(const SampleDispenser& dispenser, int ranks, bool showProgress, double timeoutSeconds,
                      bool& ranksLost)
      : dispenser_(dispenser),
        workers_(size_t(ranks - 1), Worker{.released = ranksLost, .batches = {}}),
        first_(dispenser.next()),
        showProgress_(showProgress),
        timeout_(timeoutSeconds),
        ranksLost_(ranksLost),
        alone_(ranksLost),
        progress_(ranksLost ? "rendering on rank 0 alone" : "rendering on " + std::to_string(ranks) + " ranks",
                  dispenser.remaining()) {}

  Assignment next(double secondsPerSample) override {
    secondsPerSample_ = secondsPerSample;
    answerRequests();
    // The batches of a rank given up for lost come first: the film must hold every index handed out before it
    // pauses.
    if (!reissued_.empty()) {
      const auto [first, count] = reissued_.back();
      reissued_.pop_back();
      return {Assignment::Kind::Samples, first, count};
    }
    if (pause_ == SampleDispenser::Pause::None) setPause(dispenser_.pause(secondsPerSample));
    if (pause_ == SampleDispenser::Pause::None) return {Assignment::Kind::Samples, dispenser_.take(1), 1};
    // Before a checkpoint, rank 0 goes on rendering while the others finish their batches, within the rank
    // timeout; the samples stay a prefix of the indices, as rank 0's own are done when it stops. An end waits
    // idle: it is due now.
    if (pause_ == SampleDispenser::Pause::Checkpoint && dispenser_.remaining() > 0 && !allReady() &&
        secondsPaused() < timeout_)
      return {Assignment::Kind::Samples, dispenser_.take(1), 1};
    // Every worker learns of the pause at its next request (sent as it starts its last batch) and is ready once it
    // has rendered that batch.
    while (!allReady()) {
      if (!answerRequests()) std::this_thread::sleep_for(std::chrono::microseconds(500));
      if (secondsPaused() > timeout_) {
        continueAlone();
        return next(secondsPerSample);
      }
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
    double seconds = 0.0;
    if (ranksLost_) {
      // The films of the ranks that answered, received when the others were given up.
      if (!received_.width) received_ = FilmSums::zero(film.width, film.height, film.hasAovs());
      forEachFilmChannel(film, received_, [](auto, auto& sums, const auto& values) {
        for (size_t i = 0; i < values.size(); ++i) sums[i] = sums[i] + values[i];
      });
      stats.rays += receivedStats_.rays;
      stats.invalidSamples += receivedStats_.invalidSamples;
      received_ = FilmSums();
      receivedStats_ = FrameStats();
    } else {
      for (size_t i = 0; i < workers_.size(); ++i) tellCombine(int(i + 1), Combine::Reduce, timeout_);
      seconds = reduceFilm(film, stats, timeout_);
    }
    backend.loadFilm(film);
    if (pause_ == SampleDispenser::Pause::End && showProgress_) {
      progress_.update(dispenser_.next() - first_);
      progress_.finish();
      // What the scaling model of docs/performance.md needs: the time to add up the films.
      if (alone_)
        std::fprintf(stderr, "rank 0 rendered the %u samples per pixel alone\n", dispenser_.next() - first_);
      else if (ranksLost_)
        std::fprintf(stderr, "rank 0 rendered %u of the %u samples per pixel, with the films the other ranks sent\n",
                     ownDone_, dispenser_.next() - first_);
      else
        std::fprintf(stderr,
                     "films of %zu ranks (%.1f MiB each) added up in %.3f s; rank 0 rendered %u of the %u "
                     "samples per pixel\n",
                     workers_.size() + 1, double(film.bytes()) / double(1 << 20), seconds, ownDone_,
                     dispenser_.next() - first_);
    }
    pause_ = SampleDispenser::Pause::None;
    for (Worker& w : workers_) {
      w.ready = false;
      w.batches.clear();  // in the film now
    }
    return true;
  }

  uint32_t completed() const override { return dispenser_.next(); }
  void checkpointWritten() override { dispenser_.checkpointWritten(); }
  RenderEnd end() const override { return dispenser_.end(); }

 private:
  struct Worker {
    uint32_t done = 0;
    bool ready = false;     // in combine(): its batches rendered, waiting to be told how to combine
    bool released = false;  // rendering no more: its film was received, or it was given up for lost
    std::vector<std::pair<uint32_t, uint32_t>> batches;  // first and count of each handed out since the last combine
  };

  void setPause(SampleDispenser::Pause pause) {
    pause_ = pause;
    if (pause_ != SampleDispenser::Pause::None) pausedAt_ = std::chrono::steady_clock::now();
  }
  double secondsPaused() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - pausedAt_).count();
  }

  bool allReady() const {
    return std::all_of(workers_.begin(), workers_.end(), [](const Worker& w) { return w.ready || w.released; });
  }

  // Some ranks did not finish their batches within the rank timeout (stopped, hung, or on a dead node): no
  // collective can include them any more. The ranks that are waiting in combine() send rank 0 their films and
  // are done; the batches of the silent ones go to rank 0 again, which renders them and the rest of the render
  // alone, so that the image and the checkpoints are still written.
  void continueAlone() {
    std::fprintf(stderr,
                 "candela: warning: %s did not finish %s batches within %d s (--rank-timeout); rank 0 renders %s "
                 "samples again and the rest of the render alone\n",
                 silentRanks().c_str(), silentCount() == 1 ? "its" : "their", int(timeout_),
                 silentCount() == 1 ? "its" : "their");
    ranksLost_ = true;
    for (size_t i = 0; i < workers_.size(); ++i) {
      Worker& w = workers_[i];
      if (w.released) continue;
      if (w.ready) {
        tellCombine(int(i + 1), Combine::SendAndStop, timeout_);
        addFilmFromRank(int(i + 1), received_, receivedStats_, timeout_);
      } else {
        reissued_.insert(reissued_.end(), w.batches.begin(), w.batches.end());
        w.done = 0;
      }
      w.batches.clear();
      w.released = true;
    }
  }

  int silentCount() const {
    return int(
        std::count_if(workers_.begin(), workers_.end(), [](const Worker& w) { return !w.ready && !w.released; }));
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
      if (!workers_[i].ready && !workers_[i].released) ranks += (count++ ? ", " : "") + std::to_string(i + 1);
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

  // Receives every message of type T with `tag` that has arrived, from any worker, and calls `received(rank,
  // message)` with each; returns whether there were any.
  template <class T, class Received>
  static bool receiveArrived(int tag, const Received& received) {
    bool any = false;
    for (;;) {
      int arrived = 0;
      MPI_Status status;
      checkMpi(MPI_Iprobe(MPI_ANY_SOURCE, tag, MPI_COMM_WORLD, &arrived, &status), "waiting for the ranks");
      if (!arrived) return any;
      any = true;
      T message;
      checkMpi(MPI_Recv(&message, sizeof message, MPI_BYTE, status.MPI_SOURCE, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE),
               "receiving a rank's message");
      received(status.MPI_SOURCE, message);
    }
  }

  // Answers the requests that have arrived and notes the ranks that became ready; returns whether there were any.
  bool answerRequests() {
    const bool ready = noteReadyRanks();
    return receiveArrived<Request>(kRequestTag, [&](int rank, const Request& request) { answer(rank, request); }) ||
           ready;
  }

  void answer(int rank, const Request& request) {
    Worker& worker = workers_[size_t(rank - 1)];
    if (worker.released) {  // a rank given up for lost that answers after all: it ends (noteReadyRanks)
      const Answer end{uint32_t(Assignment::Kind::End), dispenser_.next(), uint32_t(RenderEnd::Complete)};
      checkMpi(MPI_Send(&end, sizeof end, MPI_BYTE, rank, kAssignmentTag, MPI_COMM_WORLD), "sending an assignment");
      return;
    }
    worker.done = request.samplesDone;
    if (request.stopSignal != 0) StopOnSignals::forward(int(request.stopSignal));
    const uint32_t count = batchSize(request.secondsPerSample);
    // The rank renders its current batch before this one: the time limit must allow for both.
    if (pause_ == SampleDispenser::Pause::None) setPause(dispenser_.pause(2.0 * count * request.secondsPerSample));
    Answer answer;
    if (pause_ == SampleDispenser::Pause::None) {
      answer.kind = uint32_t(Assignment::Kind::Samples);
      answer.first = dispenser_.take(count);
      answer.count = dispenser_.next() - answer.first;
      if (answer.count > 0) worker.batches.emplace_back(answer.first, answer.count);
    } else {
      answer.kind =
          uint32_t(pause_ == SampleDispenser::Pause::End ? Assignment::Kind::End : Assignment::Kind::Checkpoint);
      answer.first = dispenser_.next();
      answer.count = uint32_t(dispenser_.end());
    }
    checkMpi(MPI_Send(&answer, sizeof answer, MPI_BYTE, rank, kAssignmentTag, MPI_COMM_WORLD), "sending an assignment");
  }

  // Notes the workers that arrived in combine() since the last call; returns whether there were any. A rank
  // given up for lost that arrives after all is told to discard its film: its samples are rendered again.
  bool noteReadyRanks() {
    return receiveArrived<uint32_t>(kReadyTag, [&](int rank, uint32_t samplesDone) {
      Worker& worker = workers_[size_t(rank - 1)];
      if (worker.released) {
        tellCombine(rank, Combine::DiscardAndStop, timeout_);
        return;
      }
      worker.done = samplesDone;
      worker.ready = true;
    });
  }

  SampleDispenser dispenser_;
  std::vector<Worker> workers_;
  SampleDispenser::Pause pause_ = SampleDispenser::Pause::None;
  std::chrono::steady_clock::time_point pausedAt_;  // when pause_ was set
  uint32_t first_;
  bool showProgress_;
  double timeout_;
  double secondsPerSample_ = 0.0;
  uint32_t ownDone_ = 0;
  bool& ranksLost_;
  const bool alone_;  // made once ranks were lost: every worker was let go before this schedule began
  std::vector<std::pair<uint32_t, uint32_t>> reissued_;  // batches of ranks given up for lost, to render here
  FilmSums received_;                                    // the films of the ranks that stopped with their films
  FrameStats receivedStats_;
  ProgressReporter progress_;
};

class WorkerSchedule final : public SampleSchedule {
 public:
  WorkerSchedule(double timeoutSeconds, bool& released) : timeout_(timeoutSeconds), stopped_(released) {}

  Assignment next(double secondsPerSample) override {
    if (stopped_) return {Assignment::Kind::End};
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
    if (stopped_) return false;
    // The film is read before rank 0 hears that this rank is ready: from then on rank 0 counts on it, and a rank
    // that stopped later would end the job.
    FilmSums film = backend.readFilm();
    uint32_t how = 0;
    MPI_Request request;
    checkMpi(MPI_Irecv(&how, 1, MPI_UINT32_T, 0, kCombineTag, MPI_COMM_WORLD, &request), "starting to add up");
    MPI_Request ready;
    checkMpi(MPI_Isend(&done_, sizeof done_, MPI_BYTE, 0, kReadyTag, MPI_COMM_WORLD, &ready), "starting to add up");
    waitPolitely(ready, timeout_, "telling rank 0 that the batches are done");
    // Rank 0 may first wait up to the timeout for a silent rank, after its own sample.
    waitPolitely(request, 3.0 * timeout_, "waiting for rank 0 to add up the films");
    if (Combine(how) == Combine::Reduce)
      reduceFilm(film, stats, timeout_);
    else if (Combine(how) == Combine::SendAndStop)
      sendFilmToRankZero(film, stats, timeout_);
    stopped_ = Combine(how) != Combine::Reduce;
    // Rank 0 holds these samples now (or renders them again); the film starts again for the next ones.
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
  bool& stopped_;  // rank 0 renders the rest alone (the team's `released`)
  uint32_t done_ = 0, completed_ = 0;
  RenderEnd end_ = RenderEnd::Complete;
};

}  // namespace

std::unique_ptr<SampleSchedule> makeCoordinatorSchedule(const SampleDispenser& dispenser, int ranks, bool showProgress,
                                                        double timeoutSeconds, bool& ranksLost) {
  return std::make_unique<CoordinatorSchedule>(dispenser, ranks, showProgress, timeoutSeconds, ranksLost);
}

std::unique_ptr<SampleSchedule> makeWorkerSchedule(double timeoutSeconds, bool& released) {
  return std::make_unique<WorkerSchedule>(timeoutSeconds, released);
}

}  // namespace candela
