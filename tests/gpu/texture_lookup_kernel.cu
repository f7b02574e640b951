#include <cuda_runtime.h>

#include <stdexcept>
#include <string>

#include "texture_lookup_kernel.h"

namespace candela::test {

namespace {

__global__ void lookUp(TexelArrays arrays, int32_t index, const Vec2* uvs, Vec4* out, uint32_t count) {
  uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i < count) out[i] = sampleTexture(arrays, index, uvs[i]);
}

void check(cudaError_t result, const char* what) {
  if (result != cudaSuccess) throw std::runtime_error(std::string(what) + ": " + cudaGetErrorString(result));
}

}  // namespace

std::vector<Vec4> sampleTextureOnDevice(const TexelArrays& deviceArrays, int32_t index, const std::vector<Vec2>& uvs) {
  const uint32_t count = uint32_t(uvs.size());
  Vec2* deviceUvs = nullptr;
  Vec4* deviceOut = nullptr;
  std::vector<Vec4> out(count);
  check(cudaMalloc(&deviceUvs, count * sizeof(Vec2)), "allocating the coordinates");
  check(cudaMalloc(&deviceOut, count * sizeof(Vec4)), "allocating the results");
  check(cudaMemcpy(deviceUvs, uvs.data(), count * sizeof(Vec2), cudaMemcpyHostToDevice), "uploading coordinates");
  lookUp<<<(count + 127) / 128, 128>>>(deviceArrays, index, deviceUvs, deviceOut, count);
  check(cudaGetLastError(), "launching the lookups");
  check(cudaMemcpy(out.data(), deviceOut, count * sizeof(Vec4), cudaMemcpyDeviceToHost), "reading the results");
  cudaFree(deviceUvs);
  cudaFree(deviceOut);
  return out;
}

}  // namespace candela::test
