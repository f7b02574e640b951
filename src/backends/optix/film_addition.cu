#include "backends/optix/film_addition.h"

namespace candela::optix {

namespace {

__global__ void addPixels(FilmView to, FilmView from, uint32_t first, uint32_t count, bool withAovs) {
  const uint32_t k = blockIdx.x * blockDim.x + threadIdx.x;
  if (k >= count) return;
  const uint32_t i = first + k;
  to.radiance[i] = to.radiance[i] + from.radiance[i];
  to.samples[i] += from.samples[i];
  if (!withAovs) return;
  to.emission[i] = to.emission[i] + from.emission[i];
  to.albedo[i] = to.albedo[i] + from.albedo[i];
  to.normal[i] = to.normal[i] + from.normal[i];
  to.depth[i] += from.depth[i];
  to.luminanceSquares[i] += from.luminanceSquares[i];
  to.oddLuminance[i] += from.oddLuminance[i];
  to.oddSamples[i] += from.oddSamples[i];
}

}  // namespace

void addFilmPixels(const FilmView& destination, const FilmView& source, uint32_t first, uint32_t count, bool withAovs,
                   cudaStream_t stream) {
  constexpr uint32_t kBlock = 256;
  if (count == 0) return;
  addPixels<<<(count + kBlock - 1) / kBlock, kBlock, 0, stream>>>(destination, source, first, count, withAovs);
}

}  // namespace candela::optix
