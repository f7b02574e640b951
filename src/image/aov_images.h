#pragma once
#include <vector>

#include "image/image.h"
#include "kernel/film.h"

namespace candela {

// The integrator's auxiliary outputs per pixel (kernel/aovs.h), the mean over the pixel's samples: the albedo
// at the first non-specular vertex, its shading normal (world space; a mean, so shorter than unit where the
// samples disagree, zero where every path escaped) and the path length to it (zero where every path escaped).
// With them the part of the image's radiance the camera sees emitted (PathResult::emitted), which the denoisers
// keep out of what they demodulate, and the variance of each pixel's mean luminance (kernel/film.h's
// meanLuminanceVariance, kUnknownVariance where a pixel has fewer than two samples), which tells them how noisy
// the pixel is; with it the unbiased one-degree-of-freedom estimate from the pixel's two halves of samples
// (halvesVariance), which tells them how much of that is left for stratified samples.
struct AovImages {
  Image albedo;
  Image normal;
  std::vector<float> depth;
  Image emission;
  std::vector<float> variance;
  std::vector<float> halvesVariance;

  AovImages() = default;
  AovImages(uint32_t width, uint32_t height)
      : albedo(width, height),
        normal(width, height),
        depth(size_t(width) * height, 0.0f),
        emission(width, height),
        variance(size_t(width) * height, kUnknownVariance),
        halvesVariance(size_t(width) * height, kUnknownVariance) {}
  uint32_t width() const { return albedo.width; }
  uint32_t height() const { return albedo.height; }
};

}  // namespace candela
