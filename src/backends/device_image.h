#pragma once
#include <array>

#include "core/math.h"

namespace candela {

// A backend's image as it lives in GPU memory, for consumers on the same GPU (the viewer's CUDA-OpenGL interop)
// that take it without a round trip through the host. Backend::deviceImage() gives it where there is one.
class DeviceImage {
 public:
  virtual ~DeviceImage() = default;

  // The UUID of the CUDA device that holds the image (cudaDeviceProp::uuid).
  virtual std::array<unsigned char, 16> deviceUuid() const = 0;
  // readImage's pixels written to `destination`, device memory of width * height Vec3 on that device.
  virtual void writeImageToDevice(Vec3* destination) const = 0;
};

}  // namespace candela
