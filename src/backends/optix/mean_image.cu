#include "backends/optix/mean_image.h"

namespace candela::optix {

namespace {

__global__ void meanPixels(FilmView film, uint32_t count, Vec3* mean) {
  const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i < count) mean[i] = filmMean(film.radiance[i], film.samples[i]);
}

}  // namespace

void writeMeanImage(const FilmView& film, uint32_t count, Vec3* mean, cudaStream_t stream) {
  constexpr uint32_t kBlock = 256;
  if (count == 0) return;
  meanPixels<<<(count + kBlock - 1) / kBlock, kBlock, 0, stream>>>(film, count, mean);
}

}  // namespace candela::optix
