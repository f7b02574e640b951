#pragma once
// A noisy 1080p frame with its guides, the input of the filter benchmarks. The filters' cost does not depend on
// the pixel values (every tap is weighed, none skipped, but for taps that are all zero), so random data stands in for
// a render.
#include <random>

#include "image/aov_images.h"

namespace candela::bench {

struct FilterInput {
  Image color;
  AovImages aovs;
};

inline FilterInput noisyFrame(uint32_t width = 1920, uint32_t height = 1080) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  FilterInput in{Image(width, height), AovImages(width, height)};
  for (size_t i = 0; i < in.color.pixels.size(); ++i) {
    in.color.pixels[i] = Vec3{u(rng), u(rng), u(rng)} * 2.0f;
    in.aovs.albedo.pixels[i] = {0.2f + 0.6f * u(rng), 0.5f, 0.5f};
    in.aovs.normal.pixels[i] = normalize(Vec3{0.1f * u(rng), 1.0f, 0.1f * u(rng)});
    in.aovs.depth[i] = 2.0f + 0.01f * u(rng);
  }
  return in;
}

// The frame with emitted light in the top `percent` percent of its rows (a sky, say) added to its colour. The
// emission's a-trous passes skip the rows (and on the CPU the columns) far from any: 100 is their worst case.
inline FilterInput withEmission(FilterInput in, int percent) {
  const size_t rows = size_t(in.color.height) * size_t(percent) / 100;
  for (size_t i = 0; i < rows * in.color.width; ++i) {
    in.aovs.emission.pixels[i] = Vec3{1.0f, 0.9f, 0.8f} * (1.0f + 0.1f * in.color.pixels[i].x);
    in.color.pixels[i] = in.color.pixels[i] + in.aovs.emission.pixels[i];
  }
  return in;
}

}  // namespace candela::bench
