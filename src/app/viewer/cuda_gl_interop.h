#pragma once
// A backend's image in GPU memory to the display texture without leaving the GPU: the backend writes it into an
// OpenGL pixel buffer registered with CUDA, and the texture is filled from that buffer.
#include <cstddef>
#include <cstdint>
#include <string>

#include "app/viewer/gl.h"
#include "app/viewer/image_display.h"
#include "backends/device_image.h"

struct cudaGraphicsResource;

namespace candela {

class CudaGlInterop {
 public:
  // Needs a current OpenGL context. Throws std::runtime_error saying why when interop cannot work here: the
  // context runs on another device than the image's GPU (their UUIDs differ; `deviceName` names the GPU in the
  // message), or CUDA refuses the buffer.
  CudaGlInterop(const DeviceImage& image, const std::string& deviceName);
  ~CudaGlInterop();
  CudaGlInterop(const CudaGlInterop&) = delete;
  CudaGlInterop& operator=(const CudaGlInterop&) = delete;

  // The backend's current image (width x height, as its settings say) into `display`.
  void transfer(ImageDisplay& display, uint32_t width, uint32_t height);

 private:
  void resize(size_t bytes);
  void release() noexcept;

  const DeviceImage& image_;
  GLuint buffer_ = 0;
  size_t bytes_ = 0;
  cudaGraphicsResource* resource_ = nullptr;
};

}  // namespace candela
