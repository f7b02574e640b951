#include "app/distributed/mpi_team.h"

#include <climits>
#include <string>

#include "app/distributed/distributed_schedule.h"

namespace candela {

namespace {

constexpr int kFailureTag = 103;

std::string messageOf(const std::exception_ptr& failure) {
  try {
    std::rethrow_exception(failure);
  } catch (const std::exception& e) {
    return e.what();
  } catch (...) {
    return "an unknown error";
  }
}

}  // namespace

void MpiTeam::agree(std::exception_ptr failure) {
  const int rank = session_.rank();
  int mine = failure ? rank : INT_MAX, first = INT_MAX;
  MPI_Request request;
  checkMpi(MPI_Iallreduce(&mine, &first, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD, &request), "agreeing on the start");
  waitPolitely(request, timeout_, "waiting for the other ranks to load the scene");
  if (first == INT_MAX) return;
  std::string message;
  if (rank == first) message = messageOf(failure);
  if (first != 0 && rank == first)
    checkMpi(MPI_Send(message.data(), int(message.size()), MPI_CHAR, 0, kFailureTag, MPI_COMM_WORLD),
             "reporting a failure");
  if (first != 0 && rank == 0) {
    MPI_Status status;
    checkMpi(MPI_Probe(first, kFailureTag, MPI_COMM_WORLD, &status), "receiving a failure");
    int length = 0;
    MPI_Get_count(&status, MPI_CHAR, &length);
    message.resize(size_t(length));
    checkMpi(MPI_Recv(message.data(), length, MPI_CHAR, first, kFailureTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE),
             "receiving a failure");
  }
  if (rank != 0) throw AgreedFailure("");
  throw AgreedFailure("rank " + std::to_string(first) + " of " + std::to_string(session_.size()) + ": " + message);
}

std::unique_ptr<SampleSchedule> MpiTeam::schedule(const SampleDispenser& dispenser, bool showProgress) {
  if (writes()) return makeCoordinatorSchedule(dispenser, session_.size(), showProgress, timeout_);
  return makeWorkerSchedule(timeout_);
}

}  // namespace candela
