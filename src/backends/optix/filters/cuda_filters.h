#pragma once
// The CPU filters of image/filters in CUDA: the same per-tap arithmetic (atrous_kernel.h, bilateral_kernel.h)
// summed in the same order, on images in device memory.
#include <cuda_runtime.h>

#include "backends/optix/device_buffer.h"
#include "image/aov_images.h"
#include "image/filters/atrous.h"
#include "image/filters/bilateral.h"

namespace candela::optix {

// The a-trous filter's inputs in device memory, each multiplied by `scale` as it is read: 1 for means, 1 / (sample
// count) for a film that holds sums.
struct DeviceFilmView {
  const Vec3* color = nullptr;
  const Vec3* albedo = nullptr;
  const Vec3* normal = nullptr;
  const float* depth = nullptr;
  float scale = 1.0f;
};

// The a-trous filter of image/filters/atrous.h, holding its scratch planes for one image size.
class CudaAtrous {
 public:
  CudaAtrous(uint32_t width, uint32_t height);
  uint32_t width() const { return width_; }
  uint32_t height() const { return height_; }
  // Enqueues the filter on `stream`; `output` is device memory for width * height pixels. Validate the params
  // with validateAtrousParams first.
  void run(const DeviceFilmView& film, Vec3* output, const AtrousParams& params, cudaStream_t stream);

 private:
  uint32_t width_, height_;
  DeviceBuffer planes_;         // colour twice (ping-pong) and the guides, one float plane each
  DeviceBuffer luminanceSum_;   // one double
};

// Enqueues the bilateral filter of image/filters/bilateral.h on `stream` for the image input * scale; input and
// output are device memory.
void cudaBilateral(const Vec3* input, float scale, Vec3* output, uint32_t width, uint32_t height,
                   const BilateralParams& params, cudaStream_t stream);

// Host images in, host image out (upload, filter, download): for tests and one-off use.
Image atrousDenoiseCuda(const Image& color, const AovImages& aovs, const AtrousParams& params);
Image bilateralFilterCuda(const Image& input, const BilateralParams& params);

}  // namespace candela::optix
