#pragma once
#include <vector>

#include "image/image.h"

namespace candela {

// The integrator's auxiliary outputs per pixel (kernel/aovs.h), the mean over the pixel's samples: the albedo
// at the first non-specular vertex, its shading normal (world space; a mean, so shorter than unit where the
// samples disagree, zero where every path escaped) and the path length to it (zero where every path escaped).
struct AovImages {
  Image albedo;
  Image normal;
  std::vector<float> depth;

  AovImages() = default;
  AovImages(uint32_t width, uint32_t height)
      : albedo(width, height), normal(width, height), depth(size_t(width) * height, 0.0f) {}
  uint32_t width() const { return albedo.width; }
  uint32_t height() const { return albedo.height; }
};

}  // namespace candela
