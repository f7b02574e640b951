#pragma once
// The OptiX backend's image to the display texture without leaving the GPU: the backend writes it into an
// OpenGL pixel buffer registered with CUDA, and the texture is filled from that buffer.
#include <cstddef>
#include <cstdint>

#include "app/viewer/gl.h"
#include "app/viewer/image_display.h"
#include "backends/optix/optix_backend.h"

struct cudaGraphicsResource;

namespace candela {

class CudaGlInterop {
 public:
  // Needs a current OpenGL context. Throws std::runtime_error saying why when interop cannot work here: the
  // context runs on another device than the backend's GPU (their UUIDs differ), or CUDA refuses the buffer.
  explicit CudaGlInterop(const OptixBackend& backend);
  ~CudaGlInterop();
  CudaGlInterop(const CudaGlInterop&) = delete;
  CudaGlInterop& operator=(const CudaGlInterop&) = delete;

  // The backend's current image (width x height, as its settings say) into `display`.
  void transfer(ImageDisplay& display, uint32_t width, uint32_t height);

 private:
  void resize(size_t bytes);
  void release() noexcept;

  const OptixBackend& backend_;
  GLuint buffer_ = 0;
  size_t bytes_ = 0;
  cudaGraphicsResource* resource_ = nullptr;
};

}  // namespace candela
