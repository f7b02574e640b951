#include "backends/optix/optix_error.h"

#include <optix.h>
#include <optix_stubs.h>

#include <cstdio>
#include <fstream>
#include <regex>

namespace candela::optix {

namespace {

// The oldest driver branch that carries the OptiX ABI of the headers this build was compiled with.
const char* minimumDriverForHeaders() {
  if (OPTIX_VERSION >= 90000) return "570";
  if (OPTIX_VERSION >= 80100) return "555";
  if (OPTIX_VERSION >= 80000) return "535";
  return "530";
}

std::string headersVersion() {
  return std::to_string(OPTIX_VERSION / 10000) + "." + std::to_string(OPTIX_VERSION % 10000 / 100);
}

}  // namespace

std::string formatBytes(size_t bytes) {
  char buffer[32];
  if (bytes >= (size_t(1) << 30))
    std::snprintf(buffer, sizeof buffer, "%.2f GiB", double(bytes) / double(size_t(1) << 30));
  else
    std::snprintf(buffer, sizeof buffer, "%.1f MiB", double(bytes) / double(size_t(1) << 20));
  return buffer;
}

std::string nvidiaDriverVersion() {
  std::ifstream file("/proc/driver/nvidia/version");
  std::string line;
  std::getline(file, line);
  std::smatch match;
  if (std::regex_search(line, match, std::regex(R"(Kernel Module(?: for [^ ]+)?\s+([0-9]+\.[0-9.]+))")))
    return match[1];
  return "unknown";
}

void checkCuda(cudaError_t result, const char* what) {
  if (result == cudaSuccess) return;
  cudaGetLastError();  // clear a non-sticky error so that later calls do not report it again
  if (result == cudaErrorMemoryAllocation) {
    size_t free = 0, total = 0;
    cudaMemGetInfo(&free, &total);
    throw std::runtime_error(std::string("out of device memory during ") + what + " (" + formatBytes(free) + " of " +
                             formatBytes(total) + " free)");
  }
  throw std::runtime_error(std::string("CUDA error during ") + what + ": " + cudaGetErrorString(result) + " (" +
                           cudaGetErrorName(result) + ")");
}

void checkOptix(OptixResult result, const char* what) {
  if (result == OPTIX_SUCCESS) return;
  std::string code = " (OptiX error " + std::to_string(int(result)) + ")";
  switch (result) {
    case OPTIX_ERROR_LIBRARY_NOT_FOUND:
      throw OptixError(result, "the NVIDIA driver's OptiX library libnvoptix.so.1 was not found" + code +
                                   ": install the full NVIDIA driver, " + minimumDriverForHeaders() + " or newer");
    case OPTIX_ERROR_UNSUPPORTED_ABI_VERSION:
      throw OptixError(result, "the NVIDIA driver " + nvidiaDriverVersion() + " is too old for OptiX " +
                                   headersVersion() + " (ABI " + std::to_string(OPTIX_ABI_VERSION) + ")" + code +
                                   ": install driver " + minimumDriverForHeaders() + " or newer");
    case OPTIX_ERROR_DEVICE_OUT_OF_MEMORY:
      throw OptixError(result, std::string("out of device memory during ") + what + code);
    default: break;
  }
  throw OptixError(result, std::string("OptiX failed during ") + what + ": " + optixGetErrorName(result) + code);
}

}  // namespace candela::optix
