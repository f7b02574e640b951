#pragma once
// Images as separate float planes per channel, the layout the CPU filters' row loops vectorise over.
#include <vector>

#include "image/image.h"

namespace candela {

struct RgbPlanes {
  uint32_t width = 0, height = 0;
  std::vector<float> r, g, b;

  RgbPlanes() = default;
  RgbPlanes(uint32_t w, uint32_t h) : width(w), height(h), r(size_t(w) * h), g(r.size()), b(r.size()) {}
  explicit RgbPlanes(const Image& image) : RgbPlanes(image.width, image.height) {
    for (size_t i = 0; i < r.size(); ++i) set(i, image.pixels[i]);
  }
  void set(size_t i, Vec3 c) {
    r[i] = c.x;
    g[i] = c.y;
    b[i] = c.z;
  }
  Vec3 get(size_t i) const { return {r[i], g[i], b[i]}; }
  Image toImage() const {
    Image image(width, height);
    for (size_t i = 0; i < r.size(); ++i) image.pixels[i] = get(i);
    return image;
  }
};

// Per-row sums of weighted colour and of the weights.
struct RowSums {
  std::vector<float> r, g, b, weight;
  explicit RowSums(uint32_t width) : r(width), g(width), b(width), weight(width) {}
  void clear() {
    std::fill(r.begin(), r.end(), 0.0f);
    std::fill(g.begin(), g.end(), 0.0f);
    std::fill(b.begin(), b.end(), 0.0f);
    std::fill(weight.begin(), weight.end(), 0.0f);
  }
};

}  // namespace candela
