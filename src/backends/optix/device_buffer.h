#pragma once
// One allocation of device memory, owned; failing allocations say how much was asked for and for what.
// cudaMalloc aligns to 256 bytes, more than OptiX asks of acceleration structures and SBT records.
#include <cuda.h>

#include <cstddef>
#include <vector>

namespace candela::optix {

class DeviceBuffer {
 public:
  DeviceBuffer() = default;
  // `purpose` names the contents for the out-of-memory message ("the accumulation buffer").
  DeviceBuffer(size_t bytes, const char* purpose);
  ~DeviceBuffer();
  DeviceBuffer(DeviceBuffer&& other) noexcept;
  DeviceBuffer& operator=(DeviceBuffer&& other) noexcept;
  DeviceBuffer(const DeviceBuffer&) = delete;
  DeviceBuffer& operator=(const DeviceBuffer&) = delete;

  // A buffer holding a copy of `values`; empty vectors give an empty buffer (null pointer).
  template <class T>
  static DeviceBuffer fromVector(const std::vector<T>& values, const char* purpose) {
    DeviceBuffer buffer(values.size() * sizeof(T), purpose);
    buffer.upload(values.data(), buffer.size());
    return buffer;
  }

  void upload(const void* source, size_t bytes);
  void download(void* destination, size_t bytes) const;

  size_t size() const { return bytes_; }
  CUdeviceptr address() const { return CUdeviceptr(pointer_); }
  template <class T>
  T* as() const {
    return static_cast<T*>(pointer_);
  }

 private:
  void* pointer_ = nullptr;
  size_t bytes_ = 0;
};

}  // namespace candela::optix
