#pragma once
#include "backends/backend.h"
#include "backends/film_sums.h"

namespace candela {

// Adds every rank's film and statistics onto rank 0, in double precision: the result differs from a single
// process's sums only in the order of the additions. Collective over MPI_COMM_WORLD. On rank 0 `film` and `stats`
// become the sums; elsewhere they are left as they are. The film goes in slices of a few MiB, so that the
// reduction needs little memory beyond the film's. Returns the seconds the additions took, from when every rank
// had come to them.
double reduceFilm(FilmSums& film, FrameStats& stats, double timeoutSeconds);

// Without a collective, for when a rank has stopped answering (the others cannot meet it in one): a rank sends its
// film and statistics to rank 0, which adds them to `film` and `stats` in float, as the film itself adds; an
// empty `film` becomes one of the sender's size (the ranks compared their renders before starting).
void sendFilmToRankZero(const FilmSums& film, const FrameStats& stats, double timeoutSeconds);
void addFilmFromRank(int rank, FilmSums& film, FrameStats& stats, double timeoutSeconds);

}  // namespace candela
