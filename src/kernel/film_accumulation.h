#pragma once
// The one routine that adds path samples to a film (kernel/film.h), shared by the CPU backend and the OptiX raygen
// program.
#include "kernel/film.h"
#include "kernel/integrator.h"

namespace candela {

struct PixelTally {
  uint32_t rays = 0;
  uint32_t invalidSamples = 0;  // dropped: NaN, infinite or negative, or a sum they would have made infinite
};

// One pixel's value of every channel of the film (kernel/film_channels.h).
struct FilmPixel {
#define CANDELA_FILM_PIXEL_VALUE(Type, name, ...) Type name{};
  CANDELA_FILM_CHANNELS(CANDELA_FILM_PIXEL_VALUE)
#undef CANDELA_FILM_PIXEL_VALUE
};

// One pixel's sums while samples are added to them: loaded from the film once and stored back once. Without the
// AOVs the channels that exist only with them stay zero.
template <bool kWithAovs>
struct PixelSums : FilmPixel {
  CANDELA_HD static PixelSums load(const FilmView& film, size_t pixel) {
    PixelSums s;
    forEachFilmChannel(s, film, [&](auto channel, auto& value, const auto* values) {
      if (channel.inFilm(kWithAovs)) value = values[pixel];
    });
    return s;
  }

  CANDELA_HD void store(const FilmView& film, size_t pixel) const {
    forEachFilmChannel(*this, film, [&](auto channel, const auto& value, auto* values) {
      if (channel.inFilm(kWithAovs)) values[pixel] = value;
    });
  }

  // Adds the path's sample unless it is invalid or would make a sum infinite (finite samples can: a sum of two
  // values near the float maximum overflows); returns whether it was added. A dropped sample adds nothing, AOVs
  // included, so every sum of the pixel holds the same samples. `sampleIndex` is the sample's index in the pixel's
  // sequence, whose parity says its half.
  CANDELA_HD bool add(const PathResult& path, uint32_t sampleIndex) {
    if (!isValidSample(path.radiance) || !isValidSample(path.emitted)) return false;
    const Vec3 r = radiance + path.radiance, e = emission + path.emitted;
    if (!isFinite(r) || !isFinite(e) || samples == 0xFFFFFFFFu) return false;
    if (kWithAovs) {
      const Vec3 a = albedo + path.aovs.albedo, n = normal + path.aovs.normal;
      const float d = depth + path.aovs.depth;
      if (!isFinite(a) || !isFinite(n) || !isFinite(d)) return false;
      albedo = a;
      normal = n;
      depth = d;
      // Only a guide: where a sample's square overflows, the sum saturates instead of dropping the sample.
      const float l = luminance(path.radiance), squares = luminanceSquares + l * l;
      luminanceSquares = squares < 3.0e38f ? squares : 3.0e38f;
      if (sampleIndex & 1u) {
        const float odd = oddLuminance + l;
        oddLuminance = odd < 3.0e38f ? odd : 3.0e38f;
        ++oddSamples;
      }
    }
    radiance = r;
    emission = e;
    ++samples;
    return true;
  }
};

// Adds samples firstSample .. firstSample + count - 1 to pixel `pixel` of the film; sampleAt(i) traces sample i and
// returns its PathResult.
template <bool kWithAovs, class SampleAt>
CANDELA_HD PixelTally accumulatePixel(const FilmView& film, size_t pixel, uint32_t firstSample, uint32_t count,
                                      const SampleAt& sampleAt) {
  PixelSums<kWithAovs> sums = PixelSums<kWithAovs>::load(film, pixel);
  PixelTally tally;
  for (uint32_t i = firstSample; i < firstSample + count; ++i) {
    const PathResult path = sampleAt(i);
    tally.rays += path.rays;
    if (!sums.add(path, i)) ++tally.invalidSamples;
  }
  sums.store(film, pixel);
  return tally;
}

}  // namespace candela
