#pragma once
#include "image/image.h"

namespace candela {

// Guide layers from the first non-specular hit of each pixel, the size of the beauty image. Either may be
// absent; the denoiser then works from colour alone.
struct DenoiserGuides {
  const Image* albedo = nullptr;  // linear reflectance
  const Image* normal = nullptr;  // world-space unit normals
};

// Denoises a linear HDR image with the OptiX AI denoiser: the AOV model, which OptiX 9 uses for HDR input in
// place of the deprecated HDR model, with a beauty layer and the given guides. Throws std::runtime_error with
// one sentence when it cannot run: no usable GPU, or a driver without the denoiser's weights (OptiX 7990).
Image denoiseWithOptix(const Image& beauty, const DenoiserGuides& guides = {});

}  // namespace candela
