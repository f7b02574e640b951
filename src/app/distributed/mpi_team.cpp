#include "app/distributed/mpi_team.h"

#include <climits>
#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "app/distributed/distributed_schedule.h"

namespace candela {

namespace {

constexpr int kFailureTag = 103,
              kReleaseTag = 106;  // beside distributed_schedule.cpp's 101, 102, 105, 107 and film_reduction.cpp's 104

std::string messageOf(const std::exception_ptr& failure) {
  try {
    std::rethrow_exception(failure);
  } catch (const std::exception& e) {
    return e.what();
  } catch (...) {
    return "an unknown error";
  }
}

// An identity as one text: name and value, each ended by a zero byte.
std::string encode(const ExrAttributes& identity) {
  std::string text;
  for (const auto& [name, value] : identity) text += name + '\0' + value + '\0';
  return text;
}

ExrAttributes decode(const std::string& text) {
  ExrAttributes identity;
  for (size_t at = 0; at < text.size();) {
    const size_t nameEnd = text.find('\0', at), valueEnd = text.find('\0', nameEnd + 1);
    if (nameEnd == std::string::npos || valueEnd == std::string::npos) break;
    identity.emplace_back(text.substr(at, nameEnd - at), text.substr(nameEnd + 1, valueEnd - nameEnd - 1));
    at = valueEnd + 1;
  }
  return identity;
}

// The first setting in which `mine` differs from `writer`'s, as a sentence; empty when none does.
std::string firstDifference(const ExrAttributes& writer, const ExrAttributes& mine) {
  for (const auto& [name, value] : mine) {
    std::string theirs = "(none)";
    for (const auto& [writerName, writerValue] : writer)
      if (writerName == name) theirs = writerValue;
    if (theirs != value)
      return "renders another job than rank 0: its " + name.substr(name.find('.') + 1) + " is '" + value +
             "', rank 0's is '" + theirs + "'";
  }
  return "";
}

}  // namespace

void MpiTeam::checkSameRender(const ExrAttributes& identity) {
  if (ranksLost_ || released_) return;  // rank 0 renders alone, or has let this rank go
  writersIdentity_ = encode(identity);
  identityLength_ = writersIdentity_.size();
  MPI_Request request;
  checkMpi(MPI_Ibcast(&identityLength_, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD, &request), "comparing the render");
  if (!awaitTeam(request, "waiting for the other ranks to load the scene")) return;
  if (identityLength_ > uint64_t(INT_MAX))
    throw std::runtime_error("comparing the render: rank 0's settings are too long");
  writersIdentity_.resize(size_t(identityLength_));
  checkMpi(MPI_Ibcast(writersIdentity_.data(), int(identityLength_), MPI_CHAR, 0, MPI_COMM_WORLD, &request),
           "comparing the render");
  if (!awaitTeam(request, "comparing the render")) return;
  std::exception_ptr failure;
  if (const std::string difference = firstDifference(decode(writersIdentity_), identity); !difference.empty())
    failure = std::make_exception_ptr(std::runtime_error(difference));
  agree(failure);
}

void MpiTeam::agree(std::exception_ptr failure) {
  const int rank = session_.rank();
  if (ranksLost_) {  // rank 0, alone: its failure is the team's
    if (failure) throw AgreedFailure("rank 0 of " + std::to_string(session_.size()) + ": " + messageOf(failure));
    return;
  }
  if (released_) {  // rank 0 renders alone and needs nothing more of this rank
    if (failure) throw AgreedFailure("");
    return;
  }
  failingRank_ = failure ? rank : INT_MAX;
  firstFailingRank_ = INT_MAX;
  MPI_Request request;
  checkMpi(MPI_Iallreduce(&failingRank_, &firstFailingRank_, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD, &request),
           "agreeing on the start");
  if (!awaitTeam(request, "waiting for the other ranks to load the scene")) {
    agree(failure);  // as rank 0 alone, or as a rank let go
    return;
  }
  const int first = firstFailingRank_;
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

bool MpiTeam::awaitTeam(MPI_Request& request, const char* what) {
  if (!rendered_) {
    waitPolitely(request, timeout_, what);
    return true;
  }
  if (writes()) {
    if (waitPolitelyUntil(request, timeout_, "waiting for the other ranks between frames") == WaitEnd::Completed)
      return true;
    goOnAlone();
    return false;
  }
  // Rank 0 may first wait up to the timeout for a silent rank, then writes its frame.
  const double patience = 3.0 * timeout_;
  const WaitEnd end =
      waitPolitelyUntil(request, patience, "waiting for rank 0 between frames", [this] { return releaseArrived(); });
  if (end == WaitEnd::TimedOut) throw rankTimeoutError(patience, "waiting for rank 0 between frames");
  released_ = end == WaitEnd::Stopped;
  return end == WaitEnd::Completed;
}

void MpiTeam::goOnAlone() {
  std::fprintf(stderr,
               "candela: warning: the ranks did not all come to the next frame within %d s (--rank-timeout); rank 0 "
               "lets them go and renders the remaining frames alone\n",
               int(timeout_));
  ranksLost_ = true;
  warnedAlone_ = true;
  // Rank 0 cannot tell which rank is missing from a collective step: every other rank is told, and one that is
  // stopped learns of it if it comes back. The value is static, as the sends are not waited for.
  static const uint32_t release = 1;
  for (int rank = 1; rank < session_.size(); ++rank) {
    MPI_Request request;
    checkMpi(MPI_Isend(&release, 1, MPI_UINT32_T, rank, kReleaseTag, MPI_COMM_WORLD, &request),
             "letting the other ranks go");
    MPI_Request_free(&request);
  }
}

bool MpiTeam::releaseArrived() {
  int arrived = 0;
  checkMpi(MPI_Iprobe(0, kReleaseTag, MPI_COMM_WORLD, &arrived, MPI_STATUS_IGNORE), "waiting for rank 0");
  if (!arrived) return false;
  uint32_t release = 0;
  checkMpi(MPI_Recv(&release, 1, MPI_UINT32_T, 0, kReleaseTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE),
           "waiting for rank 0");
  return true;
}

std::unique_ptr<SampleSchedule> MpiTeam::schedule(const SampleDispenser& dispenser, bool showProgress) {
  rendered_ = true;
  if (!writes()) return makeWorkerSchedule(timeout_, released_);
  if (ranksLost_ && !warnedAlone_) {
    std::fprintf(stderr,
                 "candela: warning: the other ranks were let go when a rank stopped answering; rank 0 "
                 "renders the remaining frames alone\n");
    warnedAlone_ = true;
  }
  return makeCoordinatorSchedule(dispenser, session_.size(), showProgress, timeout_, ranksLost_);
}

}  // namespace candela
