#pragma once
// The CPU filters of image/filters in CUDA: the same per-tap arithmetic (atrous_kernel.h, bilateral_kernel.h)
// summed in the same order, on images in device memory.
#include <cuda_runtime.h>

#include "backends/optix/device_buffer.h"
#include "image/aov_images.h"
#include "image/filters/atrous.h"
#include "image/filters/bilateral.h"
#include "kernel/film.h"

namespace candela::optix {

// The a-trous filter of image/filters/atrous.h, holding its scratch planes for one image size.
class CudaAtrous {
 public:
  CudaAtrous(uint32_t width, uint32_t height);
  uint32_t width() const { return width_; }
  uint32_t height() const { return height_; }
  // Enqueues the filter of the film's means on `stream`; the film needs its AOVs, and `output` is device memory for
  // width * height pixels. For images of means, the film has no sample counts and `imageVariance` and
  // `imageHalvesVariance` hold AovImages::variance and halvesVariance (null for a film). Validate the params with
  // validateAtrousParams first.
  void run(const FilmView& film, const float* imageVariance, const float* imageHalvesVariance, Vec3* output,
           const AtrousParams& params, cudaStream_t stream);

 private:
  uint32_t width_, height_;
  DeviceBuffer planes_;        // colour twice (ping-pong) and the guides, one float plane each
  DeviceBuffer luminanceSum_;  // one double
};

// Enqueues the bilateral filter of image/filters/bilateral.h on `stream` for the film's mean radiance, without its
// emission (which is added back after) where the film has an emission image; film and output are device memory.
void cudaBilateral(const FilmView& film, Vec3* output, uint32_t width, uint32_t height, const BilateralParams& params,
                   cudaStream_t stream);

// Enqueues means[i] = sums[i] / samples[i] (0 where a pixel has no sample) for `pixels` pixels: a film channel as
// an image of means, to filter beside other images of means.
void cudaMeans(const Vec3* sums, const uint32_t* samples, Vec3* means, size_t pixels, cudaStream_t stream);

// Host images in, host image out (upload, filter, download): for tests and one-off use.
Image atrousDenoiseCuda(const Image& color, const AovImages& aovs, const AtrousParams& params);
Image bilateralFilterCuda(const Image& input, const BilateralParams& params);

}  // namespace candela::optix
