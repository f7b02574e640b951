#include "app/distributed/film_reduction.h"

#include <mpi.h>

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "app/distributed/mpi_session.h"

namespace candela {

namespace {

constexpr size_t kSliceValues = size_t(1) << 20;  // doubles per reduction: 8 MiB

// Adds `count` values of type T at `values` over the ranks, onto rank 0, a slice at a time.
template <class T>
void reduceValues(T* values, size_t count, int rank, double timeoutSeconds) {
  std::vector<double> send(std::min(count, kSliceValues)), receive(rank == 0 ? send.size() : 0);
  for (size_t begin = 0; begin < count; begin += kSliceValues) {
    const size_t n = std::min(kSliceValues, count - begin);
    std::copy(values + begin, values + begin + n, send.begin());
    MPI_Request request;
    checkMpi(MPI_Ireduce(send.data(), rank == 0 ? receive.data() : nullptr, int(n), MPI_DOUBLE, MPI_SUM, 0,
                         MPI_COMM_WORLD, &request),
             "adding up the films");
    waitActively(request, timeoutSeconds, "adding up the films");
    if (rank == 0)
      for (size_t i = 0; i < n; ++i) values[begin + i] = T(receive[i]);
  }
}

// A film channel's values as numbers to add: a Vec3 is three floats.
template <class T>
std::pair<T*, size_t> numbers(std::vector<T>& values) {
  return {values.data(), values.size()};
}
std::pair<float*, size_t> numbers(std::vector<Vec3>& values) {
  return {values.empty() ? nullptr : &values[0].x, values.size() * 3};
}

}  // namespace

double reduceFilm(FilmSums& film, FrameStats& stats, double timeoutSeconds) {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Request arrived;
  checkMpi(MPI_Ibarrier(MPI_COMM_WORLD, &arrived), "waiting for the ranks' films");
  waitPolitely(arrived, timeoutSeconds, "waiting for the ranks' films");
  const double start = MPI_Wtime();
  // Channel by channel, each value on its own: the order of the channels changes no sum.
  forEachFilmChannel(film, [&](auto, auto& values) {
    const auto [first, count] = numbers(values);
    reduceValues(first, count, rank, timeoutSeconds);
  });
  unsigned long long counts[2] = {stats.rays, stats.invalidSamples}, sums[2] = {0, 0};
  MPI_Request request;
  checkMpi(MPI_Ireduce(counts, sums, 2, MPI_UNSIGNED_LONG_LONG, MPI_SUM, 0, MPI_COMM_WORLD, &request),
           "adding up the ray counts");
  waitActively(request, timeoutSeconds, "adding up the ray counts");
  if (rank == 0) {
    stats.rays = sums[0];
    stats.invalidSamples = sums[1];
  }
  return MPI_Wtime() - start;
}

namespace {

constexpr int kFilmTag = 104;
constexpr size_t kMessageBytes = size_t(1) << 30;  // MPI counts are ints: a channel goes in messages of 1 GiB

void sendBytes(const void* data, size_t bytes, double timeoutSeconds) {
  for (size_t begin = 0; begin < bytes; begin += kMessageBytes) {
    MPI_Request request;
    checkMpi(MPI_Isend(static_cast<const char*>(data) + begin, int(std::min(kMessageBytes, bytes - begin)), MPI_BYTE, 0,
                       kFilmTag, MPI_COMM_WORLD, &request),
             "sending the film");
    waitActively(request, timeoutSeconds, "sending the film");
  }
}

void receiveBytes(void* data, size_t bytes, int rank, double timeoutSeconds) {
  for (size_t begin = 0; begin < bytes; begin += kMessageBytes) {
    MPI_Request request;
    checkMpi(MPI_Irecv(static_cast<char*>(data) + begin, int(std::min(kMessageBytes, bytes - begin)), MPI_BYTE, rank,
                       kFilmTag, MPI_COMM_WORLD, &request),
             "receiving a film");
    waitActively(request, timeoutSeconds, "receiving a film");
  }
}

template <class T>
void add(T& sum, const T& value) {
  sum = sum + value;
}

}  // namespace

void sendFilmToRankZero(const FilmSums& film, const FrameStats& stats, double timeoutSeconds) {
  const uint32_t shape[3] = {film.width, film.height, film.hasAovs() ? 1u : 0u};
  sendBytes(shape, sizeof shape, timeoutSeconds);
  forEachFilmChannel(film, [&](auto channel, const auto& values) {
    sendBytes(values.data(), values.size() * sizeof(typename decltype(channel)::Type), timeoutSeconds);
  });
  const uint64_t counts[2] = {stats.rays, stats.invalidSamples};
  sendBytes(counts, sizeof counts, timeoutSeconds);
}

void addFilmFromRank(int rank, FilmSums& film, FrameStats& stats, double timeoutSeconds) {
  uint32_t shape[3] = {0, 0, 0};
  receiveBytes(shape, sizeof shape, rank, timeoutSeconds);
  if (film.width == 0) film = FilmSums::zero(shape[0], shape[1], shape[2] != 0);
  if (shape[0] != film.width || shape[1] != film.height || (shape[2] != 0) != film.hasAovs())
    throw std::runtime_error("rank " + std::to_string(rank) + " sent a film of another size");
  FilmSums received = FilmSums::zero(film.width, film.height, film.hasAovs());
  forEachFilmChannel(received, film, [&](auto channel, auto& values, auto& sums) {
    receiveBytes(values.data(), values.size() * sizeof(typename decltype(channel)::Type), rank, timeoutSeconds);
    for (size_t i = 0; i < values.size(); ++i) add(sums[i], values[i]);
  });
  uint64_t counts[2] = {0, 0};
  receiveBytes(counts, sizeof counts, rank, timeoutSeconds);
  stats.rays += counts[0];
  stats.invalidSamples += counts[1];
}

}  // namespace candela
