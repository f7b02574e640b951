#pragma once
#include <functional>

#include "image/aov_images.h"
#include "image/image.h"

namespace candela {

// The OptiX AI denoiser over an image read back and its albedo and normal guides. The function keeps the
// denoiser's model and device memory for every image after the first, so that a sequence of frames makes them once.
using OptixAiDenoise = std::function<Image(const Image& beauty, const AovImages& guides)>;

// Makes one. Throws std::runtime_error with one sentence where it cannot run: not in this build (it comes with
// the OptiX backend), no usable GPU, or no denoiser weights in the driver (OptiX error 7990).
OptixAiDenoise makeOptixAiDenoiser();

}  // namespace candela
