#include "backends/optix/device_buffer.h"

#include <cuda_runtime.h>

#include <stdexcept>
#include <string>
#include <utility>

#include "backends/optix/optix_error.h"

namespace candela::optix {

DeviceBuffer::DeviceBuffer(size_t bytes, const char* purpose) : bytes_(bytes) {
  if (bytes == 0) return;
  cudaError_t result = cudaMalloc(&pointer_, bytes);
  if (result == cudaErrorMemoryAllocation) {
    cudaGetLastError();
    size_t free = 0, total = 0;
    cudaMemGetInfo(&free, &total);
    throw std::runtime_error("out of device memory: asked for " + formatBytes(bytes) + " for " + purpose + " with " +
                             formatBytes(free) + " of " + formatBytes(total) + " free");
  }
  checkCuda(result, purpose);
}

DeviceBuffer::~DeviceBuffer() {
  if (pointer_) cudaFree(pointer_);
}

DeviceBuffer::DeviceBuffer(DeviceBuffer&& other) noexcept
    : pointer_(std::exchange(other.pointer_, nullptr)), bytes_(std::exchange(other.bytes_, 0)) {}

DeviceBuffer& DeviceBuffer::operator=(DeviceBuffer&& other) noexcept {
  if (this != &other) {
    if (pointer_) cudaFree(pointer_);
    pointer_ = std::exchange(other.pointer_, nullptr);
    bytes_ = std::exchange(other.bytes_, 0);
  }
  return *this;
}

void DeviceBuffer::upload(const void* source, size_t bytes) {
  if (bytes > bytes_) throw std::logic_error("DeviceBuffer::upload past the end of the buffer");
  if (bytes > 0) checkCuda(cudaMemcpy(pointer_, source, bytes, cudaMemcpyHostToDevice), "a host-to-device copy");
}

void DeviceBuffer::download(void* destination, size_t bytes) const {
  if (bytes > bytes_) throw std::logic_error("DeviceBuffer::download past the end of the buffer");
  if (bytes > 0) checkCuda(cudaMemcpy(destination, pointer_, bytes, cudaMemcpyDeviceToHost), "a device-to-host copy");
}

}  // namespace candela::optix
