#include "backends/optix/device_display.h"

#include "backends/optix/display_pixels.h"
#include "backends/optix/optix_error.h"

namespace candela::optix {

void DeviceDisplay::PinnedBytes::reserve(size_t bytes) {
  if (bytes <= size) return;
  if (data) cudaFreeHost(data);
  data = nullptr;
  size = 0;
  checkCuda(cudaMallocHost(reinterpret_cast<void**>(&data), bytes), "allocating pinned host memory for a frame");
  size = bytes;
}

DeviceDisplay::PinnedBytes::~PinnedBytes() {
  if (data) cudaFreeHost(data);
}

DeviceDisplay::DeviceDisplay() {
  checkCuda(cudaEventCreate(&sourceStart_), "creating a CUDA event");
  checkCuda(cudaEventCreate(&sourceEnd_), "creating a CUDA event");
}

DeviceDisplay::~DeviceDisplay() {
  cudaEventDestroy(sourceStart_);
  cudaEventDestroy(sourceEnd_);
}

DisplayFrame DeviceDisplay::read(const std::function<LinearPixels()>& enqueueSource, bool timeSource,
                                 const DisplaySettings& display, uint32_t divisor, cudaStream_t stream) {
  if (table_.size() == 0) {
    table_ = DeviceBuffer(sizeof(SrgbByteTable), "the sRGB byte table");
    table_.upload(&srgbByteTable(), sizeof(SrgbByteTable));
  }
  checkCuda(cudaEventRecord(sourceStart_, stream), "recording a CUDA event");
  const LinearPixels source = enqueueSource();
  checkCuda(cudaEventRecord(sourceEnd_, stream), "recording a CUDA event");
  const DisplaySize size = displaySize(source.width, source.height, divisor);
  const size_t bytes = size_t(size.width) * size.height * 3;
  if (pixels_.size() < bytes) {
    pixels_ = DeviceBuffer();
    pixels_ = DeviceBuffer(bytes, "the display frame");
  }
  enqueueDisplayPixels(source, divisor, displayMapping(display), table_.as<SrgbByteTable>(), pixels_.as<uint8_t>(),
                       stream);
  checkCuda(cudaGetLastError(), "launching the display frame");
  PinnedBytes& host = host_[next_];
  next_ = 1 - next_;
  host.reserve(bytes);
  checkCuda(cudaMemcpyAsync(host.data, pixels_.as<void>(), bytes, cudaMemcpyDeviceToHost, stream),
            "reading the display frame back");
  checkCuda(cudaStreamSynchronize(stream), "making the display frame");
  DisplayFrame frame;
  frame.width = size.width;
  frame.height = size.height;
  frame.rgb = host.data;
  if (timeSource) {
    float milliseconds = 0.0f;
    checkCuda(cudaEventElapsedTime(&milliseconds, sourceStart_, sourceEnd_), "reading a CUDA event");
    frame.filterMilliseconds = milliseconds;
  }
  return frame;
}

}  // namespace candela::optix
