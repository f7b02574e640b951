#include "backends/optix/mean_image.h"

namespace candela::optix {

namespace {

__global__ void scalePixels(const Vec3* sum, uint32_t count, float scale, Vec3* mean) {
  const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i < count) mean[i] = sum[i] * scale;
}

}  // namespace

void writeMeanImage(const Vec3* sum, uint32_t count, float scale, Vec3* mean, cudaStream_t stream) {
  constexpr uint32_t kBlock = 256;
  if (count == 0) return;
  scalePixels<<<(count + kBlock - 1) / kBlock, kBlock, 0, stream>>>(sum, count, scale, mean);
}

}  // namespace candela::optix
