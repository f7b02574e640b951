#pragma once
// CUDA and OptiX results turned into exceptions that carry one plain sentence.
#include <cuda_runtime.h>
#include <optix_types.h>

#include <cstddef>
#include <stdexcept>
#include <string>

namespace candela::optix {

class OptixError : public std::runtime_error {
 public:
  OptixError(OptixResult code, const std::string& message) : std::runtime_error(message), code_(code) {}
  OptixResult code() const { return code_; }

 private:
  OptixResult code_;
};

// Throws std::runtime_error naming `what` (the operation) when `result` is not cudaSuccess.
void checkCuda(cudaError_t result, const char* what);

// Throws OptixError naming `what` when `result` is not OPTIX_SUCCESS; the well-known causes (library missing,
// driver too old, out of memory) get a sentence that says what to do.
void checkOptix(OptixResult result, const char* what);

// "1.25 GiB", "512 MiB": for messages about device memory.
std::string formatBytes(size_t bytes);

// The NVIDIA driver's version string ("580.159.04") when the kernel module reports one, else "unknown".
std::string nvidiaDriverVersion();

}  // namespace candela::optix
