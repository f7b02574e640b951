#include "app/distributed/mpi_session.h"

#include <chrono>
#include <cstdlib>
#include <stdexcept>
#include <thread>

namespace candela {

void checkMpi(int code, const char* what) {
  if (code == MPI_SUCCESS) return;
  char text[MPI_MAX_ERROR_STRING];
  int length = 0;
  MPI_Error_string(code, text, &length);
  throw std::runtime_error(std::string(what) + ": " + std::string(text, size_t(length)));
}

MpiSession::MpiSession() {
  int provided = 0;
  checkMpi(MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided), "starting MPI");
  // A failed call returns its error here; the callers turn it into one line and end the job.
  MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  MPI_Comm node;
  checkMpi(MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank_, MPI_INFO_NULL, &node),
           "grouping the ranks by node");
  MPI_Comm_rank(node, &localRank_);
  MPI_Comm_free(&node);
}

MpiSession::~MpiSession() { MPI_Finalize(); }

void MpiSession::abort(int status) const {
  MPI_Abort(MPI_COMM_WORLD, status);
  std::_Exit(status);
}

namespace {

// Tests `request` until it completes, `timeoutSeconds` pass or `stopWaiting` returns true, sleeping `pause`
// between the tests (doubling up to a millisecond) or not at all.
WaitEnd wait(MPI_Request& request, double timeoutSeconds, const std::string& what, std::chrono::microseconds pause,
             const std::function<bool()>& stopWaiting) {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  for (;;) {
    int done = 0;
    checkMpi(MPI_Test(&request, &done, MPI_STATUS_IGNORE), what.c_str());
    if (done) return WaitEnd::Completed;
    if (stopWaiting && stopWaiting()) return WaitEnd::Stopped;
    if (std::chrono::duration<double>(Clock::now() - start).count() > timeoutSeconds) return WaitEnd::TimedOut;
    if (pause.count() == 0) continue;
    std::this_thread::sleep_for(pause);
    pause = std::min(pause * 2, std::chrono::microseconds(1000));
  }
}

}  // namespace

std::runtime_error rankTimeoutError(double timeoutSeconds, const std::string& what) {
  return std::runtime_error(what + ": no answer for " + std::to_string(int(timeoutSeconds)) +
                            " s (--rank-timeout); a rank has stopped or hangs");
}

void waitPolitely(MPI_Request& request, double timeoutSeconds, const std::string& what) {
  if (waitPolitelyUntil(request, timeoutSeconds, what) != WaitEnd::Completed)
    throw rankTimeoutError(timeoutSeconds, what);
}

WaitEnd waitPolitelyUntil(MPI_Request& request, double timeoutSeconds, const std::string& what,
                          const std::function<bool()>& stopWaiting) {
  // Short sleeps at first: a reply is usually there at once.
  return wait(request, timeoutSeconds, what, std::chrono::microseconds(20), stopWaiting);
}

void waitActively(MPI_Request& request, double timeoutSeconds, const std::string& what) {
  if (wait(request, timeoutSeconds, what, std::chrono::microseconds(0), {}) != WaitEnd::Completed)
    throw rankTimeoutError(timeoutSeconds, what);
}

}  // namespace candela
