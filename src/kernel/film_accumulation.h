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

// One pixel's sums while samples are added to them: loaded from the film once and stored back once.
template <bool kWithAovs>
struct PixelSums {
  Vec3 radiance;
  Vec3 emission;  // with the AOVs only, as PathResult::emitted
  PathAovs aovs;
  float luminanceSquares = 0.0f, oddLuminance = 0.0f;
  uint32_t samples = 0, oddSamples = 0;

  CANDELA_HD static PixelSums load(const FilmView& film, size_t pixel) {
    PixelSums s;
    s.radiance = film.radiance[pixel];
    s.samples = film.samples[pixel];
    if (kWithAovs) {
      s.emission = film.emission[pixel];
      s.aovs = {film.albedo[pixel], film.normal[pixel], film.depth[pixel]};
      s.luminanceSquares = film.luminanceSquares[pixel];
      s.oddLuminance = film.oddLuminance[pixel];
      s.oddSamples = film.oddSamples[pixel];
    }
    return s;
  }

  CANDELA_HD void store(const FilmView& film, size_t pixel) const {
    film.radiance[pixel] = radiance;
    film.samples[pixel] = samples;
    if (kWithAovs) {
      film.emission[pixel] = emission;
      film.albedo[pixel] = aovs.albedo;
      film.normal[pixel] = aovs.normal;
      film.depth[pixel] = aovs.depth;
      film.luminanceSquares[pixel] = luminanceSquares;
      film.oddLuminance[pixel] = oddLuminance;
      film.oddSamples[pixel] = oddSamples;
    }
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
      const PathAovs a{aovs.albedo + path.aovs.albedo, aovs.normal + path.aovs.normal, aovs.depth + path.aovs.depth};
      if (!isFinite(a.albedo) || !isFinite(a.normal) || !isFinite(a.depth)) return false;
      aovs = a;
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
