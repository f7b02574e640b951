#pragma once
// The CUDA devices of the machine, for code that chooses among them (no OptiX headers needed).
#include <string>
#include <vector>

namespace candela::optix {

// How many CUDA devices there are, at least one. Throws std::runtime_error with the sentence OptixContext gives
// when there is no usable GPU (no CUDA device, no or too old a driver). Defined with those checks in
// optix_context.cpp.
int cudaDeviceCount();

// The names of the CUDA devices, by index ("NVIDIA H200"); throws as cudaDeviceCount does.
std::vector<std::string> gpuNames();

// Makes CUDA device `ordinal` current on this thread for the scope's life, then the one before again: the
// backends of several devices in one process each issue their work on their own device.
class CurrentDevice {
 public:
  explicit CurrentDevice(int ordinal);
  ~CurrentDevice();
  CurrentDevice(const CurrentDevice&) = delete;
  CurrentDevice& operator=(const CurrentDevice&) = delete;

 private:
  int previous_ = 0;
};

}  // namespace candela::optix
