#include "backends/cpu/host_film.h"

#include <stdexcept>

namespace candela {

void HostFilm::reset(uint32_t width, uint32_t height, bool withAovs) {
  sums_ = FilmSums::zero(width, height, withAovs);
}

FilmView HostFilm::view() {
  FilmView v;
  forEachFilmChannel(v, sums_,
                     [](auto, auto*& pointer, auto& values) { pointer = values.empty() ? nullptr : values.data(); });
  return v;
}

void HostFilm::load(const FilmSums& sums) {
  if (!sums.sameShape(sums_)) throw std::invalid_argument("HostFilm::load: the sums have another size or AOVs");
  if (!sums.channelsFit()) throw std::invalid_argument("HostFilm::load: a channel of the sums has another size");
  sums_ = sums;
}

Image HostFilm::meanImage(const std::vector<Vec3>& sums) const {
  Image image(sums_.width, sums_.height);
  for (size_t i = 0; i < sums.size(); ++i) image.pixels[i] = filmMean(sums[i], sums_.samples[i]);
  return image;
}

Image HostFilm::readEmission() const {
  if (!hasAovs()) throw std::logic_error("HostFilm::readEmission on a film without AOVs");
  return meanImage(sums_.emission);
}

AovImages HostFilm::readAovs() const {
  if (!hasAovs()) throw std::logic_error("HostFilm::readAovs on a film without AOVs");
  const FilmSums& s = sums_;
  AovImages aovs(s.width, s.height);
  for (size_t i = 0; i < s.samples.size(); ++i) {
    aovs.albedo.pixels[i] = filmMean(s.albedo[i], s.samples[i]);
    aovs.normal.pixels[i] = filmMean(s.normal[i], s.samples[i]);
    aovs.depth[i] = filmMean(s.depth[i], s.samples[i]);
    aovs.variance[i] = meanLuminanceVariance(s.radiance[i], s.luminanceSquares[i], s.samples[i]);
    aovs.halvesVariance[i] = halvesVariance(s.radiance[i], s.oddLuminance[i], s.samples[i], s.oddSamples[i]);
  }
  aovs.emission = readEmission();
  return aovs;
}

}  // namespace candela
