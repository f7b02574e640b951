#pragma once
#include <cstdint>
#include <vector>

#include "core/math.h"

namespace candela {

// A copy in host memory of a backend's film (kernel/film.h): the per-pixel sums and sample counts, not their
// means. It is what checkpoints store and what the processes of a distributed render add together; loaded back
// into a backend, accumulation continues from it as if it had never left.
struct FilmSums {
  uint32_t width = 0, height = 0;
  std::vector<Vec3> radiance;
  std::vector<uint32_t> samples;
  // The emission sums, the AOV sums, the squared-luminance sums and the luminance sums and counts of the samples
  // of odd index (kernel/film.h); empty when the film has no AOVs.
  std::vector<Vec3> emission, albedo, normal;
  std::vector<float> depth, luminanceSquares, oddLuminance;
  std::vector<uint32_t> oddSamples;

  // A cleared film of width x height pixels, with AOV sums or without.
  static FilmSums zero(uint32_t width, uint32_t height, bool withAovs) {
    FilmSums f;
    f.width = width;
    f.height = height;
    const size_t pixels = size_t(width) * height, aovPixels = withAovs ? pixels : 0;
    f.radiance.assign(pixels, Vec3{});
    f.emission.assign(aovPixels, Vec3{});
    f.samples.assign(pixels, 0);
    f.albedo.assign(aovPixels, Vec3{});
    f.normal.assign(aovPixels, Vec3{});
    f.depth.assign(aovPixels, 0.0f);
    f.luminanceSquares.assign(aovPixels, 0.0f);
    f.oddLuminance.assign(aovPixels, 0.0f);
    f.oddSamples.assign(aovPixels, 0);
    return f;
  }

  size_t pixelCount() const { return size_t(width) * height; }
  // The bytes of the sums and counts.
  size_t bytes() const {
    return (radiance.size() + emission.size() + albedo.size() + normal.size()) * sizeof(Vec3) +
           (samples.size() + oddSamples.size()) * sizeof(uint32_t) +
           (depth.size() + luminanceSquares.size() + oddLuminance.size()) * sizeof(float);
  }
  bool hasAovs() const { return !albedo.empty(); }
  bool sameShape(const FilmSums& other) const {
    return width == other.width && height == other.height && hasAovs() == other.hasAovs();
  }
};

}  // namespace candela
