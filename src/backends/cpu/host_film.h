#pragma once
#include <cstdint>
#include <vector>

#include "backends/film_sums.h"
#include "image/aov_images.h"
#include "image/image.h"
#include "kernel/film.h"

namespace candela {

// The CPU backend's film: the per-pixel sums of kernel/film.h in host memory, and their means as images.
class HostFilm {
 public:
  // Clears the film to width x height pixels, with AOV sums or without.
  void reset(uint32_t width, uint32_t height, bool withAovs);
  bool hasAovs() const { return sums_.hasAovs(); }
  FilmView view();

  const FilmSums& sums() const { return sums_; }
  // Replaces the sums with `sums`, which must have the film's size and AOVs and a value per pixel in each of its
  // channels (FilmSums::channelsFit); else throws std::invalid_argument.
  void load(const FilmSums& sums);

  Image readImage() const { return meanImage(sums_.radiance); }
  // Throw std::logic_error when the film has no AOV sums (the emission is recorded with them).
  Image readEmission() const;
  AovImages readAovs() const;

 private:
  Image meanImage(const std::vector<Vec3>& sums) const;

  FilmSums sums_;
};

}  // namespace candela
