#pragma once
#include <cstdint>
#include <vector>

#include "core/math.h"

namespace candela {

// Linear RGB radiance, row-major, top row first.
struct Image {
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<Vec3> pixels;

  Image() = default;
  Image(uint32_t w, uint32_t h) : width(w), height(h), pixels(size_t(w) * h) {}
  Vec3& at(uint32_t x, uint32_t y) { return pixels[size_t(y) * width + x]; }
  const Vec3& at(uint32_t x, uint32_t y) const { return pixels[size_t(y) * width + x]; }
};

}  // namespace candela
