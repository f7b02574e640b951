#include "backends/optix/optix_error.h"
#include "backends/optix/pixel_counters.h"

namespace candela::optix {

namespace {

constexpr int kThreads = 256;
constexpr int kMaxBlocks = 1024;

__global__ void sumCountersKernel(const PixelCounters* counters, uint32_t count, CounterTotals* totals) {
  unsigned long long rays = 0, invalid = 0;
  for (uint32_t i = blockIdx.x * blockDim.x + threadIdx.x; i < count; i += gridDim.x * blockDim.x) {
    rays += counters[i].rays;
    invalid += counters[i].invalidSamples;
  }
  for (int offset = 16; offset > 0; offset /= 2) {
    rays += __shfl_down_sync(0xFFFFFFFFu, rays, offset);
    invalid += __shfl_down_sync(0xFFFFFFFFu, invalid, offset);
  }
  if (threadIdx.x % 32 == 0) {
    atomicAdd(&totals->rays, rays);
    atomicAdd(&totals->invalidSamples, invalid);
  }
}

}  // namespace

void sumPixelCounters(const PixelCounters* counters, uint32_t count, CounterTotals* totals, cudaStream_t stream) {
  checkCuda(cudaMemsetAsync(totals, 0, sizeof(CounterTotals), stream), "clearing the counter totals");
  int blocks = int((count + kThreads - 1) / kThreads);
  if (blocks > kMaxBlocks) blocks = kMaxBlocks;
  if (blocks == 0) return;
  sumCountersKernel<<<blocks, kThreads, 0, stream>>>(counters, count, totals);
  checkCuda(cudaGetLastError(), "summing the pixel counters");
}

}  // namespace candela::optix
