#pragma once
#include <cstdint>
#include <vector>

#include "core/math.h"
#include "kernel/film_channels.h"

namespace candela {

// A copy in host memory of a backend's film (kernel/film.h): the per-pixel sums and sample counts, not their
// means. It is what checkpoints store and what the processes of a distributed render add together; loaded back
// into a backend, accumulation continues from it as if it had never left.
struct FilmSums {
  uint32_t width = 0, height = 0;
  // A vector per channel of kernel/film_channels.h; those of the channels with AOVs only are empty when the film
  // has no AOVs.
#define CANDELA_FILM_SUMS_VECTOR(Type, name, ...) std::vector<Type> name;
  CANDELA_FILM_CHANNELS(CANDELA_FILM_SUMS_VECTOR)
#undef CANDELA_FILM_SUMS_VECTOR

  // A cleared film of width x height pixels, with AOV sums or without.
  static FilmSums zero(uint32_t width, uint32_t height, bool withAovs) {
    FilmSums f;
    f.width = width;
    f.height = height;
    const size_t pixels = size_t(width) * height;
    forEachFilmChannel(f, [&](auto channel, auto& values) {
      values.assign(channel.inFilm(withAovs) ? pixels : 0, typename decltype(channel)::Type{});
    });
    return f;
  }

  size_t pixelCount() const { return size_t(width) * height; }
  // The bytes of the sums and counts.
  size_t bytes() const {
    size_t total = 0;
    forEachFilmChannel(*this, [&](auto channel, const auto& values) {
      total += values.size() * sizeof(typename decltype(channel)::Type);
    });
    return total;
  }
  bool hasAovs() const { return !albedo.empty(); }
  // Whether every channel holds a value per pixel, but for those with AOVs only, which are empty without AOVs: what
  // the backends and the checkpoints take.
  bool channelsFit() const {
    bool fit = true;
    forEachFilmChannel(*this, [&](auto channel, const auto& values) {
      fit = fit && values.size() == (channel.inFilm(hasAovs()) ? pixelCount() : 0);
    });
    return fit;
  }
  bool sameShape(const FilmSums& other) const {
    return width == other.width && height == other.height && hasAovs() == other.hasAovs();
  }
};

}  // namespace candela
