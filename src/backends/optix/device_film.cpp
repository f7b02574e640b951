#include "backends/optix/device_film.h"

#include <stdexcept>

#include "backends/optix/optix_error.h"

namespace candela::optix {

namespace {

// Makes `buffer` hold `bytes` unless it does already; frees the old allocation first.
void resizeBuffer(DeviceBuffer& buffer, size_t bytes, const char* purpose) {
  if (buffer.size() == bytes) return;
  buffer = DeviceBuffer();
  if (bytes > 0) buffer = DeviceBuffer(bytes, purpose);
}

// The bytes of a pixel's value of the film channel `channel` (kernel/film_channels.h).
template <class Channel>
constexpr size_t bytesPerPixel(Channel) {
  return sizeof(typename Channel::Type);
}

}  // namespace

void DeviceFilm::resize(uint32_t width, uint32_t height, bool withAovs) {
  width_ = width;
  height_ = height;
  const size_t pixels = size_t(width) * height;
  forEachFilmChannel(buffers_, [&](auto channel, DeviceBuffer& buffer) {
    resizeBuffer(buffer, (channel.inFilm(withAovs) ? pixels : 0) * bytesPerPixel(channel), channel.description);
  });
}

void DeviceFilm::clear(cudaStream_t stream) {
  forEachFilmChannel(buffers_, [&](auto, DeviceBuffer& buffer) {
    if (buffer.size() > 0) checkCuda(cudaMemsetAsync(buffer.as<void>(), 0, buffer.size(), stream), "clearing the film");
  });
}

void DeviceFilm::copyPixels(const DeviceFilm& source, int sourceDevice, int device, uint32_t first, uint32_t count,
                            cudaStream_t stream) {
  if (source.width_ != width_ || source.height_ != height_ || source.hasAovs() != hasAovs())
    throw std::logic_error("DeviceFilm::copyPixels between films of other sizes or AOVs");
  if (size_t(first) + count > pixelCount()) throw std::logic_error("DeviceFilm::copyPixels past the film's end");
  forEachFilmChannel(buffers_, source.buffers_, [&](auto channel, DeviceBuffer& to, const DeviceBuffer& from) {
    if (to.size() == 0) return;
    const size_t offset = size_t(first) * bytesPerPixel(channel), bytes = size_t(count) * bytesPerPixel(channel);
    checkCuda(cudaMemcpyPeerAsync(to.as<char>() + offset, device, from.as<char>() + offset, sourceDevice, bytes,
                                  stream),
              "copying film sums between devices");
  });
}

void DeviceFilm::clearPixels(uint32_t first, uint32_t count, cudaStream_t stream) {
  if (size_t(first) + count > pixelCount()) throw std::logic_error("DeviceFilm::clearPixels past the film's end");
  forEachFilmChannel(buffers_, [&](auto channel, DeviceBuffer& buffer) {
    if (buffer.size() > 0)
      checkCuda(cudaMemsetAsync(buffer.as<char>() + size_t(first) * bytesPerPixel(channel), 0,
                                size_t(count) * bytesPerPixel(channel), stream),
                "clearing film sums");
  });
}

FilmView DeviceFilm::view() const {
  FilmView v;
  forEachFilmChannel(v, buffers_, [](auto channel, auto*& pointer, const DeviceBuffer& buffer) {
    pointer = buffer.as<typename decltype(channel)::Type>();
  });
  return v;
}

std::vector<uint32_t> DeviceFilm::downloadSamples() const {
  std::vector<uint32_t> samples(pixelCount());
  buffers_.samples.download(samples.data(), buffers_.samples.size());
  return samples;
}

Image DeviceFilm::meanImage(const DeviceBuffer& sums) const {
  Image image(width_, height_);
  sums.download(image.pixels.data(), sums.size());
  const std::vector<uint32_t> samples = downloadSamples();
  for (size_t i = 0; i < samples.size(); ++i) image.pixels[i] = filmMean(image.pixels[i], samples[i]);
  return image;
}

Image DeviceFilm::readEmission() const {
  if (!hasAovs()) throw std::logic_error("DeviceFilm::readEmission on a film without AOVs");
  return meanImage(buffers_.emission);
}

AovImages DeviceFilm::readAovs() const {
  if (!hasAovs()) throw std::logic_error("DeviceFilm::readAovs on a film without AOVs");
  const Buffers& b = buffers_;
  AovImages aovs(width_, height_);
  b.albedo.download(aovs.albedo.pixels.data(), b.albedo.size());
  b.normal.download(aovs.normal.pixels.data(), b.normal.size());
  b.depth.download(aovs.depth.data(), b.depth.size());
  std::vector<Vec3> radiance(b.samples.size() / sizeof(uint32_t));
  std::vector<float> squares(radiance.size()), oddLuminance(radiance.size());
  std::vector<uint32_t> oddSamples(radiance.size());
  b.radiance.download(radiance.data(), b.radiance.size());
  b.luminanceSquares.download(squares.data(), b.luminanceSquares.size());
  b.oddLuminance.download(oddLuminance.data(), b.oddLuminance.size());
  b.oddSamples.download(oddSamples.data(), b.oddSamples.size());
  const std::vector<uint32_t> samples = downloadSamples();
  for (size_t i = 0; i < samples.size(); ++i) {
    aovs.variance[i] = meanLuminanceVariance(radiance[i], squares[i], samples[i]);
    aovs.halvesVariance[i] = halvesVariance(radiance[i], oddLuminance[i], samples[i], oddSamples[i]);
    aovs.albedo.pixels[i] = filmMean(aovs.albedo.pixels[i], samples[i]);
    aovs.normal.pixels[i] = filmMean(aovs.normal.pixels[i], samples[i]);
    aovs.depth[i] = filmMean(aovs.depth[i], samples[i]);
  }
  aovs.emission = meanImage(b.emission);
  return aovs;
}

FilmSums DeviceFilm::download() const {
  FilmSums f = FilmSums::zero(width_, height_, hasAovs());
  forEachFilmChannel(f, buffers_, [](auto, auto& values, const DeviceBuffer& buffer) {
    if (buffer.size() > 0) buffer.download(values.data(), buffer.size());
  });
  return f;
}

void DeviceFilm::upload(const FilmSums& sums) {
  if (sums.width != width_ || sums.height != height_ || sums.hasAovs() != hasAovs())
    throw std::invalid_argument("DeviceFilm::upload: the sums have another size or AOVs");
  if (!sums.channelsFit()) throw std::invalid_argument("DeviceFilm::upload: a channel of the sums has another size");
  forEachFilmChannel(sums, buffers_, [](auto, const auto& values, DeviceBuffer& buffer) {
    if (buffer.size() > 0) buffer.upload(values.data(), buffer.size());
  });
}

}  // namespace candela::optix
