#pragma once
// The temporal filter of image/filters/temporal.h in CUDA: the same per-pixel arithmetic (temporal_kernel.h) and
// a-trous passes (cuda_atrous_passes.h), with the history kept in device memory from frame to frame.
#include <cuda_runtime.h>

#include "backends/optix/device_buffer.h"
#include "image/filters/temporal.h"
#include "kernel/camera.h"
#include "kernel/film.h"

namespace candela::optix {

// The history of one sequence of frames, in device memory, and the scratch planes of its a-trous passes.
class CudaTemporal {
 public:
  // Throws std::invalid_argument for bad params (validateTemporalParams).
  explicit CudaTemporal(TemporalParams params = {});
  // Enqueues the filter of the film's means (width x height pixels, with AOVs and emission) on `stream`, as
  // TemporalFilter::filter does for `camera`, `samples` per pixel and `filmContinues`; `output` is device memory for
  // width * height pixels. For images of means, the film has no sample counts. A film of another size than the
  // last one's starts afresh.
  void run(const FilmView& film, uint32_t width, uint32_t height, const Camera& camera, uint32_t samples,
           bool filmContinues, Vec3* output, cudaStream_t stream);
  // Forgets the history (a new scene).
  void reset();
  const TemporalParams& params() const { return params_; }

 private:
  void resize(uint32_t width, uint32_t height, cudaStream_t stream);

  TemporalParams params_;
  uint32_t width_ = 0, height_ = 0;
  bool haveHistory_ = false;
  Camera camera_;
  // The planes of TemporalFilter's histories, each in one allocation.
  DeviceBuffer base_, last_;
  DeviceBuffer planes_;    // the a-trous passes' planes
  DeviceBuffer variance_;  // the first pass's variance of each pixel's luminance
  DeviceBuffer sums_;      // the luminance sums of the reflected light and of the emission: two doubles
};

}  // namespace candela::optix
