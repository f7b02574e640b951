#include "backends/optix/display_pixels.h"

namespace candela::optix {

namespace {

__global__ void displayPixels(LinearPixels source, uint32_t divisor, DisplayMapping mapping, const SrgbByteTable* table,
                              uint32_t width, uint32_t height, uint8_t* rgb) {
  const uint32_t x = blockIdx.x * blockDim.x + threadIdx.x, y = blockIdx.y * blockDim.y + threadIdx.y;
  if (x >= width || y >= height) return;
  writeDisplayPixel(source, x, y, divisor, mapping, *table, rgb + 3 * (size_t(y) * width + x));
}

}  // namespace

void enqueueDisplayPixels(const LinearPixels& source, uint32_t divisor, const DisplayMapping& mapping,
                          const SrgbByteTable* table, uint8_t* rgb, cudaStream_t stream) {
  const uint32_t width = source.width / divisor, height = source.height / divisor;
  if (width == 0 || height == 0) return;
  const dim3 block(32, 8);
  const dim3 grid((width + block.x - 1) / block.x, (height + block.y - 1) / block.y);
  displayPixels<<<grid, block, 0, stream>>>(source, divisor, mapping, table, width, height, rgb);
}

}  // namespace candela::optix
