#include <chrono>
#include <stdexcept>

#include "backends/backend.h"
#include "backends/film_display.h"
#include "image/filters/bilateral.h"

namespace candela {

namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace

Image displaySourceImage(const Backend& backend, const DisplaySource& source) {
  struct Visitor {
    const Backend& backend;
    Image operator()(const AccumulatedImage&) const { return backend.readImage(); }
    Image operator()(const AtrousFiltered& s) const { return backend.filters().atrous(s.params); }
    Image operator()(const BilateralFiltered& s) const { return backend.filters().bilateral(s.params); }
    Image operator()(const TemporalFiltered& s) const {
      if (!s.denoiser) throw std::invalid_argument("a temporal display frame without its filter");
      return s.denoiser->denoise(s.camera, s.filmContinues);
    }
  };
  return std::visit(Visitor{backend}, source);
}

DisplayFrame HostFilmDisplay::read(const DisplayRequest& request) const {
  const Clock::time_point start = Clock::now();
  DisplayFrame frame;
  Image image;
  LinearPixels source;
  if (film_ && std::holds_alternative<AccumulatedImage>(request.source) && !request.smoothing) {
    source = {film_->radiance.data(), film_->samples.data(), film_->width, film_->height};
  } else {
    image = displaySourceImage(backend_, request.source);
    if (request.smoothing)
      image = backend_.aovsEnabled() ? bilateralFilter(image, backend_.readEmission(), *request.smoothing)
                                     : bilateralFilter(image, *request.smoothing);
    if (!std::holds_alternative<AccumulatedImage>(request.source) || request.smoothing)
      frame.filterMilliseconds = millisecondsSince(start);
    source = {image.pixels.data(), nullptr, image.width, image.height};
  }
  const DisplaySize size = displaySize(source.width, source.height, request.divisor);
  std::vector<uint8_t>& pixels = pixels_[next_];
  next_ = 1 - next_;
  pixels.resize(size_t(size.width) * size.height * 3);
  writeDisplayPixels(source, request.display, request.divisor, pixels.data());
  frame.width = size.width;
  frame.height = size.height;
  frame.rgb = pixels.data();
  frame.milliseconds = millisecondsSince(start);
  return frame;
}

}  // namespace candela
