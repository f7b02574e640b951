#pragma once
#include <memory>

#include "image/image.h"

namespace candela {

// Guide layers from the first non-specular hit of each pixel, the size of the beauty image. Either may be
// absent; the denoiser then works from colour alone.
struct DenoiserGuides {
  const Image* albedo = nullptr;  // linear reflectance
  const Image* normal = nullptr;  // world-space normals; means of samples are fine, they are made unit length
};

// Which guides a denoiser is made for.
struct DenoiserGuideKinds {
  bool albedo = false;
  bool normal = false;
};

// The OptiX AI denoiser for linear HDR images: the AOV model, which OptiX 9 uses for HDR input in place of the
// deprecated HDR model, with a beauty layer and the guides it was made for. Its context, model and device memory
// stay from one image to the next (the viewer denoises every frame) and are sized again only when the image
// size changes.
class OptixImageDenoiser {
 public:
  // Throws std::runtime_error with one sentence when it cannot run: no usable GPU, or a driver without the
  // denoiser's weights (OptiX 7990).
  explicit OptixImageDenoiser(DenoiserGuideKinds kinds);
  ~OptixImageDenoiser();
  OptixImageDenoiser(const OptixImageDenoiser&) = delete;
  OptixImageDenoiser& operator=(const OptixImageDenoiser&) = delete;

  // `guides` must hold the kinds the denoiser was made for, each the size of `beauty` (std::invalid_argument).
  Image denoise(const Image& beauty, const DenoiserGuides& guides = {});

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// One image through a denoiser made for the guides given.
Image denoiseWithOptix(const Image& beauty, const DenoiserGuides& guides = {});

}  // namespace candela
