#pragma once
// The CUDA device and the OptiX device context on it. Construction fails with one sentence when no usable
// GPU is present: no CUDA device, no or too old a driver, no OptiX library in the driver. The context keeps the
// programs OptiX compiles in the disk cache of defaultProgramCacheDirectory() (program_cache_directory.h).
#include <cuda_runtime.h>
#include <optix_types.h>

#include <string>

namespace candela::optix {

struct GpuInfo {
  std::string name;           // "NVIDIA H100 80GB HBM3"
  std::string driverVersion;  // "580.159.04"
  int cudaDriverVersion = 0;  // 13000 for CUDA 13.0
  int computeMajor = 0, computeMinor = 0;
  size_t memoryBytes = 0;
  unsigned int rtcoreVersion = 0;  // 0 when the GPU has no RT cores
};

class OptixContext {
 public:
  // On CUDA device `deviceIndex` modulo the devices there are.
  explicit OptixContext(int deviceIndex = 0);
  ~OptixContext();
  OptixContext(const OptixContext&) = delete;
  OptixContext& operator=(const OptixContext&) = delete;

  OptixDeviceContext get() const { return context_; }
  cudaStream_t stream() const { return stream_; }
  const GpuInfo& info() const { return info_; }
  int deviceOrdinal() const { return device_; }
  // The folder of OptiX's disk cache; empty when the compiled programs are not kept (the folder could not be
  // made, or OPTIX_CACHE_MAXSIZE=0).
  const std::string& cacheDirectory() const { return cacheDirectory_; }

  // One line for start-up: GPU, driver, OptiX ABI and RT-core version.
  std::string describe() const;

 private:
  OptixDeviceContext context_ = nullptr;
  cudaStream_t stream_ = nullptr;
  int device_ = 0;
  GpuInfo info_;
  std::string cacheDirectory_;
};

}  // namespace candela::optix
