#include <cuda_runtime.h>

#include <stdexcept>
#include <string>

#include "sampler_kernel.h"

namespace candela::test {

namespace {

__global__ void draw(SamplerKind kind, uint32_t pixel, uint32_t seed, float* out, uint32_t count) {
  uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= count) return;
  PathSampler sampler(pixel, i, seed, kind);
  float* o = out + 6 * size_t(i);
  o[0] = sampler.next1D();
  Vec2 a = sampler.next2D();
  o[1] = a.x;
  o[2] = a.y;
  o[3] = sampler.next1D();
  Vec2 b = sampler.next2D();
  o[4] = b.x;
  o[5] = b.y;
}

void check(cudaError_t result, const char* what) {
  if (result != cudaSuccess) throw std::runtime_error(std::string(what) + ": " + cudaGetErrorString(result));
}

}  // namespace

std::vector<float> drawPathSamplesOnDevice(SamplerKind kind, uint32_t pixel, uint32_t seed, uint32_t count) {
  float* deviceOut = nullptr;
  std::vector<float> out(6 * size_t(count));
  check(cudaMalloc(&deviceOut, out.size() * sizeof(float)), "allocating the results");
  draw<<<(count + 127) / 128, 128>>>(kind, pixel, seed, deviceOut, count);
  check(cudaGetLastError(), "launching the draws");
  check(cudaMemcpy(out.data(), deviceOut, out.size() * sizeof(float), cudaMemcpyDeviceToHost), "reading the results");
  cudaFree(deviceOut);
  return out;
}

}  // namespace candela::test
