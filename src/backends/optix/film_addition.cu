#include "backends/optix/film_addition.h"

namespace candela::optix {

namespace {

__global__ void addPixels(FilmView to, FilmView from, uint32_t first, uint32_t count, bool withAovs) {
  const uint32_t k = blockIdx.x * blockDim.x + threadIdx.x;
  if (k >= count) return;
  const uint32_t i = first + k;
  forEachFilmChannel(to, from, [&](auto channel, auto* sums, const auto* addends) {
    if (channel.inFilm(withAovs)) sums[i] = sums[i] + addends[i];
  });
}

}  // namespace

void addFilmPixels(const FilmView& destination, const FilmView& source, uint32_t first, uint32_t count, bool withAovs,
                   cudaStream_t stream) {
  constexpr uint32_t kBlock = 256;
  if (count == 0) return;
  addPixels<<<(count + kBlock - 1) / kBlock, kBlock, 0, stream>>>(destination, source, first, count, withAovs);
}

}  // namespace candela::optix
