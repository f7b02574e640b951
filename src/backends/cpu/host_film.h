#pragma once
#include <cstdint>
#include <vector>

#include "image/aov_images.h"
#include "image/image.h"
#include "kernel/film.h"

namespace candela {

// The CPU backend's film: the per-pixel sums of kernel/film.h in host memory, and their means as images.
class HostFilm {
 public:
  // Clears the film to width x height pixels, with AOV sums or without.
  void reset(uint32_t width, uint32_t height, bool withAovs);
  bool hasAovs() const { return !albedo_.empty(); }
  FilmView view();

  Image readImage() const { return meanImage(radiance_); }
  Image readEmission() const { return meanImage(emission_); }
  // Throws std::logic_error when the film has no AOV sums.
  AovImages readAovs() const;

 private:
  Image meanImage(const std::vector<Vec3>& sums) const;

  uint32_t width_ = 0, height_ = 0;
  std::vector<Vec3> radiance_, emission_;
  std::vector<uint32_t> samples_;
  std::vector<Vec3> albedo_, normal_;  // empty without AOVs
  std::vector<float> depth_, luminanceSquares_, oddLuminance_;
  std::vector<uint32_t> oddSamples_;
};

}  // namespace candela
