#pragma once
#include <mpi.h>

#include <functional>
#include <stdexcept>
#include <string>

namespace candela {

// MPI, initialised for the life of the object (threads may exist, only this one calls MPI), with errors
// returned rather than ending the process, and this process's place: its rank, the ranks, and its index among
// the ranks on its node (for picking a GPU).
class MpiSession {
 public:
  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  int localRank() const { return localRank_; }

  // Ends every rank of the job with `status`, for failures the others cannot learn of otherwise.
  [[noreturn]] void abort(int status) const;

 private:
  int rank_ = 0, size_ = 1, localRank_ = 0;
};

// Throws std::runtime_error "<what>: <MPI's error string>" unless `code` is MPI_SUCCESS.
void checkMpi(int code, const char* what);

// Waits for `request` to complete, sleeping between tests so that a waiting rank leaves its core to the
// rendering ranks; throws std::runtime_error naming `what` after `timeoutSeconds`.
void waitPolitely(MPI_Request& request, double timeoutSeconds, const std::string& what);
// The same, but returns how the wait ended instead of throwing after `timeoutSeconds`, and stops waiting as soon
// as `stopWaiting` (asked between the tests, when given) returns true. The request is left as it is unless it
// completed.
enum class WaitEnd { Completed, TimedOut, Stopped };
// The error of a wait for `what` that timed out after `timeoutSeconds`.
std::runtime_error rankTimeoutError(double timeoutSeconds, const std::string& what);
WaitEnd waitPolitelyUntil(MPI_Request& request, double timeoutSeconds, const std::string& what,
                          const std::function<bool()>& stopWaiting = {});
// The same without sleeping, for transfers under way between ranks that are all there: MPI moves a large
// message only while a rank calls it, so sleeps would slow it down many times.
void waitActively(MPI_Request& request, double timeoutSeconds, const std::string& what);

}  // namespace candela
