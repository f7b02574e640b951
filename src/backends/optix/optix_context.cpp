#include "backends/optix/optix_context.h"

#include <optix.h>
#include <optix_function_table_definition.h>
#include <optix_stubs.h>

#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "backends/optix/cuda_devices.h"
#include "backends/optix/optix_error.h"

namespace candela::optix {

namespace {

// The CUDA runtime is linked statically: the driver must support the toolkit the build used.
constexpr const char* kMinimumDriverForRuntime = CUDART_VERSION >= 13000   ? "580"
                                                 : CUDART_VERSION >= 12000 ? "525"
                                                                           : "450";

std::string cudaVersionString(int version) {
  return std::to_string(version / 1000) + "." + std::to_string(version % 1000 / 10);
}

}  // namespace

int cudaDeviceCount() {
  int count = 0;
  cudaError_t result = cudaGetDeviceCount(&count);
  if (result == cudaErrorInsufficientDriver) {
    cudaGetLastError();
    int runtime = 0;
    cudaRuntimeGetVersion(&runtime);
    std::string driver = nvidiaDriverVersion();
    if (driver == "unknown")
      throw std::runtime_error("no NVIDIA driver is loaded: the OptiX backend needs an NVIDIA GPU with driver " +
                               std::string(kMinimumDriverForRuntime) + " or newer");
    throw std::runtime_error("the NVIDIA driver " + driver + " is too old for CUDA " + cudaVersionString(runtime) +
                             ": install driver " + kMinimumDriverForRuntime + " or newer");
  }
  if (result == cudaErrorNoDevice || (result == cudaSuccess && count == 0)) {
    cudaGetLastError();
    throw std::runtime_error("no CUDA device found: the OptiX backend needs an NVIDIA GPU and its driver");
  }
  checkCuda(result, "counting CUDA devices");
  return count;
}

namespace {

// Makes device `index` modulo the device count current and returns its ordinal.
int selectDevice(int index) {
  const int count = cudaDeviceCount();
  const int device = (index % count + count) % count;
  checkCuda(cudaSetDevice(device), ("selecting CUDA device " + std::to_string(device)).c_str());
  checkCuda(cudaFree(nullptr), "creating the CUDA context");
  return device;
}

// optixInit loads libnvoptix once per process and fills the function table.
void initOptixOnce() {
  static const OptixResult result = optixInit();
  checkOptix(result, "optixInit");
}

void logFromOptix(unsigned int level, const char* tag, const char* message, void*) {
  std::fprintf(stderr, "optix [%u][%s]: %s\n", level, tag, message);
}

}  // namespace

OptixContext::OptixContext(int deviceIndex) {
  device_ = selectDevice(deviceIndex);
  cudaDeviceProp properties{};
  checkCuda(cudaGetDeviceProperties(&properties, device_), "reading the GPU's properties");
  info_.name = properties.name;
  info_.computeMajor = properties.major;
  info_.computeMinor = properties.minor;
  info_.memoryBytes = properties.totalGlobalMem;
  info_.driverVersion = nvidiaDriverVersion();
  checkCuda(cudaDriverGetVersion(&info_.cudaDriverVersion), "reading the driver's CUDA version");

  initOptixOnce();
  OptixDeviceContextOptions options{};
  // OptiX's own log is quiet unless CANDELA_OPTIX_LOG asks for a level (1 fatal ... 4 everything).
  if (const char* level = std::getenv("CANDELA_OPTIX_LOG")) {
    options.logCallbackFunction = logFromOptix;
    options.logCallbackLevel = int(std::strtol(level, nullptr, 10));
  }
  checkOptix(optixDeviceContextCreate(nullptr, &options, &context_), "creating the OptiX device context");
  checkOptix(optixDeviceContextGetProperty(context_, OPTIX_DEVICE_PROPERTY_RTCORE_VERSION, &info_.rtcoreVersion,
                                           sizeof info_.rtcoreVersion),
             "reading the RT-core version");
  // A blocking stream: plain cudaMemcpy on the default stream waits for the launches queued on it.
  checkCuda(cudaStreamCreate(&stream_), "creating a CUDA stream");
}

OptixContext::~OptixContext() {
  if (stream_) cudaStreamDestroy(stream_);
  if (context_) optixDeviceContextDestroy(context_);
}

std::string OptixContext::describe() const {
  std::string rtcores = info_.rtcoreVersion == 0 ? "none" : "version " + std::to_string(info_.rtcoreVersion);
  return info_.name + " (sm_" + std::to_string(info_.computeMajor) + std::to_string(info_.computeMinor) + ", " +
         formatBytes(info_.memoryBytes) + "), driver " + info_.driverVersion + " (CUDA " +
         cudaVersionString(info_.cudaDriverVersion) + "), OptiX ABI " + std::to_string(OPTIX_ABI_VERSION) +
         " (headers " + std::to_string(OPTIX_VERSION / 10000) + "." + std::to_string(OPTIX_VERSION % 10000 / 100) +
         "." + std::to_string(OPTIX_VERSION % 100) + "), RT cores: " + rtcores;
}

}  // namespace candela::optix
