#include "backends/optix/cuda_devices.h"

#include <cuda_runtime.h>

#include "backends/optix/optix_error.h"

namespace candela::optix {

std::vector<std::string> gpuNames() {
  std::vector<std::string> names;
  const int count = cudaDeviceCount();
  for (int i = 0; i < count; ++i) {
    cudaDeviceProp properties{};
    checkCuda(cudaGetDeviceProperties(&properties, i), "reading a GPU's properties");
    names.push_back(properties.name);
  }
  return names;
}

CurrentDevice::CurrentDevice(int ordinal) {
  checkCuda(cudaGetDevice(&previous_), "reading the current CUDA device");
  if (ordinal != previous_)
    checkCuda(cudaSetDevice(ordinal), ("selecting CUDA device " + std::to_string(ordinal)).c_str());
}

CurrentDevice::~CurrentDevice() { cudaSetDevice(previous_); }

}  // namespace candela::optix
