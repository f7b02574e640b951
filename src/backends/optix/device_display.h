#pragma once
// The OptiX backend's display frames (backends/film_display.h) made on its device: the tone mapping and the
// downscaling run there, and only the 8-bit pixels come back, in one asynchronous copy to pinned host memory.
#include <cuda_runtime.h>

#include <array>
#include <cstdint>
#include <functional>

#include "backends/film_display.h"
#include "backends/optix/device_buffer.h"

namespace candela::optix {

class DeviceDisplay {
 public:
  DeviceDisplay();
  ~DeviceDisplay();
  DeviceDisplay(const DeviceDisplay&) = delete;
  DeviceDisplay& operator=(const DeviceDisplay&) = delete;

  // Calls `enqueueSource`, which enqueues on `stream` whatever leaves the frame's linear image in device memory (a
  // filter, or nothing for the film itself) and returns where that image is; then enqueues the display pixels at
  // `divisor` and their copy to host memory, and waits for them. The frame's filterMilliseconds is the GPU time of
  // the work `enqueueSource` enqueued where `timeSource`, else 0; its milliseconds is left to the caller.
  DisplayFrame read(const std::function<LinearPixels()>& enqueueSource, bool timeSource, const DisplaySettings& display,
                    uint32_t divisor, cudaStream_t stream);

 private:
  // Page-locked host memory, which the copy engine writes without a staging copy.
  struct PinnedBytes {
    uint8_t* data = nullptr;
    size_t size = 0;
    void reserve(size_t bytes);
    ~PinnedBytes();
  };

  DeviceBuffer table_;  // srgbByteTable(), uploaded at the first read
  DeviceBuffer pixels_;
  std::array<PinnedBytes, 2> host_;  // alternately, as DisplayFrame promises
  size_t next_ = 0;
  cudaEvent_t sourceStart_ = nullptr, sourceEnd_ = nullptr;
};

}  // namespace candela::optix
