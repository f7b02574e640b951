#include "backends/optix/optix_context.h"

#include <optix.h>
#include <optix_function_table_definition.h>
#include <optix_stubs.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <system_error>

#include "backends/optix/cuda_devices.h"
#include "backends/optix/optix_error.h"
#include "backends/optix/program_cache_directory.h"

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

// Says once per process why the compiled programs are not kept (each GPU's context would say it again).
void warnCacheUnusable(const std::string& directory, const std::string& why) {
  static std::once_flag said;
  std::call_once(said, [&] {
    std::fprintf(stderr, "optix: cannot keep the compiled GPU programs in %s (%s): every start compiles them\n",
                 directory.c_str(), why.c_str());
  });
}

// Points OptiX's disk cache at defaultProgramCacheDirectory(), making the folder, or turns the cache off where
// that cannot be done. With no folder to name (no $HOME) OptiX keeps its own default. Returns the folder in use
// (OptiX's OPTIX_CACHE_PATH overrides the one set here), or nothing when the cache is off.
std::string useProgramCache(OptixDeviceContext context) {
  const std::string directory = defaultProgramCacheDirectory();
  if (!directory.empty()) {
    std::error_code error;
    std::filesystem::create_directories(directory, error);
    if (error) {
      warnCacheUnusable(directory, error.message());
      checkOptix(optixDeviceContextSetCacheEnabled(context, 0), "turning OptiX's disk cache off");
      return {};
    }
    // Where OptiX cannot open its cache there, it turns the cache off.
    if (const OptixResult result = optixDeviceContextSetCacheLocation(context, directory.c_str());
        result != OPTIX_SUCCESS) {
      warnCacheUnusable(directory, optixGetErrorString(result));
      return {};
    }
  }
  int enabled = 0;
  checkOptix(optixDeviceContextGetCacheEnabled(context, &enabled), "reading whether OptiX's disk cache is on");
  char location[4096] = {};
  checkOptix(optixDeviceContextGetCacheLocation(context, location, sizeof location),
             "reading where OptiX's disk cache is");
  return enabled ? location : "";
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
  cacheDirectory_ = useProgramCache(context_);
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
