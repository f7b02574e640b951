#pragma once
// The OptiX backend's film: the per-pixel sums of kernel/film.h in device memory, and their means as images.
#include <cuda_runtime.h>

#include <cstdint>
#include <vector>

#include "backends/film_sums.h"
#include "backends/optix/device_buffer.h"
#include "image/aov_images.h"
#include "image/image.h"
#include "kernel/film.h"

namespace candela::optix {

class DeviceFilm {
 public:
  // Sizes the film for width x height pixels, with AOV sums or without, keeping the buffers that fit already;
  // its contents are undefined until clear().
  void resize(uint32_t width, uint32_t height, bool withAovs);
  // Enqueues clearing every sum on `stream`.
  void clear(cudaStream_t stream);
  bool hasAovs() const { return buffers_.albedo.size() > 0; }
  uint32_t pixelCount() const { return width_ * height_; }
  FilmView view() const;

  // The means, after waiting for the default stream's work on the film (downloads are synchronous).
  Image readImage() const { return meanImage(buffers_.radiance); }
  // Throw std::logic_error when the film has no AOV sums (the emission is recorded with them).
  Image readEmission() const;
  AovImages readAovs() const;

  // The sums in host memory, and replacing them (same size and AOVs, and a value per pixel in each channel:
  // FilmSums::channelsFit; else std::invalid_argument); synchronous.
  FilmSums download() const;
  void upload(const FilmSums& sums);

  // Enqueues on `stream` copying `source`'s sums of the pixels [first, first + count) over this film's. `source`
  // has this film's size and AOVs (else std::logic_error) and lives on CUDA device `sourceDevice`, this film on
  // `device`: the same device, or another, peer to peer where the GPUs allow it, else through host memory.
  void copyPixels(const DeviceFilm& source, int sourceDevice, int device, uint32_t first, uint32_t count,
                  cudaStream_t stream);
  // Enqueues clearing the sums of the pixels [first, first + count) on `stream`.
  void clearPixels(uint32_t first, uint32_t count, cudaStream_t stream);

 private:
  // A buffer per channel of kernel/film_channels.h; those of the channels with AOVs only are empty without AOVs.
  struct Buffers {
#define CANDELA_DEVICE_FILM_BUFFER(Type, name, ...) DeviceBuffer name;
    CANDELA_FILM_CHANNELS(CANDELA_DEVICE_FILM_BUFFER)
#undef CANDELA_DEVICE_FILM_BUFFER
  };

  Image meanImage(const DeviceBuffer& sums) const;
  std::vector<uint32_t> downloadSamples() const;

  uint32_t width_ = 0, height_ = 0;
  Buffers buffers_;
};

}  // namespace candela::optix
