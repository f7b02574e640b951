#include "backends/cpu/host_film.h"

#include <stdexcept>

namespace candela {

void HostFilm::reset(uint32_t width, uint32_t height, bool withAovs) {
  width_ = width;
  height_ = height;
  const size_t pixels = size_t(width) * height, aovPixels = withAovs ? pixels : 0;
  radiance_.assign(pixels, Vec3{});
  emission_.assign(pixels, Vec3{});
  samples_.assign(pixels, 0);
  albedo_.assign(aovPixels, Vec3{});
  normal_.assign(aovPixels, Vec3{});
  depth_.assign(aovPixels, 0.0f);
  luminanceSquares_.assign(aovPixels, 0.0f);
  oddLuminance_.assign(aovPixels, 0.0f);
  oddSamples_.assign(aovPixels, 0);
}

FilmView HostFilm::view() {
  FilmView v{radiance_.data(), emission_.data(), samples_.data()};
  if (hasAovs()) {
    v.albedo = albedo_.data();
    v.normal = normal_.data();
    v.depth = depth_.data();
    v.luminanceSquares = luminanceSquares_.data();
    v.oddLuminance = oddLuminance_.data();
    v.oddSamples = oddSamples_.data();
  }
  return v;
}

Image HostFilm::meanImage(const std::vector<Vec3>& sums) const {
  Image image(width_, height_);
  for (size_t i = 0; i < sums.size(); ++i) image.pixels[i] = filmMean(sums[i], samples_[i]);
  return image;
}

AovImages HostFilm::readAovs() const {
  if (!hasAovs()) throw std::logic_error("HostFilm::readAovs on a film without AOVs");
  AovImages aovs(width_, height_);
  for (size_t i = 0; i < samples_.size(); ++i) {
    aovs.albedo.pixels[i] = filmMean(albedo_[i], samples_[i]);
    aovs.normal.pixels[i] = filmMean(normal_[i], samples_[i]);
    aovs.depth[i] = filmMean(depth_[i], samples_[i]);
    aovs.variance[i] = meanLuminanceVariance(radiance_[i], luminanceSquares_[i], samples_[i]);
    aovs.halvesVariance[i] = halvesVariance(radiance_[i], oddLuminance_[i], samples_[i], oddSamples_[i]);
  }
  aovs.emission = readEmission();
  return aovs;
}

}  // namespace candela
