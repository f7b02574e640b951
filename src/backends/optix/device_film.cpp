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

}  // namespace

void DeviceFilm::resize(uint32_t width, uint32_t height, bool withAovs) {
  width_ = width;
  height_ = height;
  const size_t pixels = size_t(width) * height, aovPixels = withAovs ? pixels : 0;
  resizeBuffer(radiance_, pixels * sizeof(Vec3), "the film's radiance sums");
  resizeBuffer(emission_, aovPixels * sizeof(Vec3), "the film's emission sums");
  resizeBuffer(samples_, pixels * sizeof(uint32_t), "the film's sample counts");
  resizeBuffer(albedo_, aovPixels * sizeof(Vec3), "the albedo AOV");
  resizeBuffer(normal_, aovPixels * sizeof(Vec3), "the normal AOV");
  resizeBuffer(depth_, aovPixels * sizeof(float), "the depth AOV");
  resizeBuffer(luminanceSquares_, aovPixels * sizeof(float), "the film's squared luminance sums");
  resizeBuffer(oddLuminance_, aovPixels * sizeof(float), "the film's luminance sums of odd samples");
  resizeBuffer(oddSamples_, aovPixels * sizeof(uint32_t), "the film's counts of odd samples");
}

void DeviceFilm::clear(cudaStream_t stream) {
  for (const Sums& s : sums())
    if (s.buffer->size() > 0)
      checkCuda(cudaMemsetAsync(s.buffer->as<void>(), 0, s.buffer->size(), stream), "clearing the film");
}

std::vector<DeviceFilm::Sums> DeviceFilm::sums() const {
  return {{&radiance_, sizeof(Vec3)},
          {&emission_, sizeof(Vec3)},
          {&samples_, sizeof(uint32_t)},
          {&albedo_, sizeof(Vec3)},
          {&normal_, sizeof(Vec3)},
          {&depth_, sizeof(float)},
          {&luminanceSquares_, sizeof(float)},
          {&oddLuminance_, sizeof(float)},
          {&oddSamples_, sizeof(uint32_t)}};
}

void DeviceFilm::copyPixels(const DeviceFilm& source, int sourceDevice, int device, uint32_t first, uint32_t count,
                            cudaStream_t stream) {
  if (source.width_ != width_ || source.height_ != height_ || source.hasAovs() != hasAovs())
    throw std::logic_error("DeviceFilm::copyPixels between films of other sizes or AOVs");
  if (size_t(first) + count > pixelCount()) throw std::logic_error("DeviceFilm::copyPixels past the film's end");
  const std::vector<Sums> from = source.sums(), to = sums();
  for (size_t i = 0; i < to.size(); ++i) {
    if (to[i].buffer->size() == 0) continue;
    const size_t offset = size_t(first) * to[i].bytesPerPixel, bytes = size_t(count) * to[i].bytesPerPixel;
    checkCuda(cudaMemcpyPeerAsync(to[i].buffer->as<char>() + offset, device, from[i].buffer->as<char>() + offset,
                                  sourceDevice, bytes, stream),
              "copying film sums between devices");
  }
}

void DeviceFilm::clearPixels(uint32_t first, uint32_t count, cudaStream_t stream) {
  if (size_t(first) + count > pixelCount()) throw std::logic_error("DeviceFilm::clearPixels past the film's end");
  for (const Sums& s : sums())
    if (s.buffer->size() > 0)
      checkCuda(cudaMemsetAsync(s.buffer->as<char>() + size_t(first) * s.bytesPerPixel, 0,
                                size_t(count) * s.bytesPerPixel, stream),
                "clearing film sums");
}

FilmView DeviceFilm::view() const {
  return {radiance_.as<Vec3>(),      emission_.as<Vec3>(), samples_.as<uint32_t>(),       albedo_.as<Vec3>(),
          normal_.as<Vec3>(),        depth_.as<float>(),   luminanceSquares_.as<float>(), oddLuminance_.as<float>(),
          oddSamples_.as<uint32_t>()};
}

std::vector<uint32_t> DeviceFilm::downloadSamples() const {
  std::vector<uint32_t> samples(pixelCount());
  samples_.download(samples.data(), samples_.size());
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
  return meanImage(emission_);
}

AovImages DeviceFilm::readAovs() const {
  if (!hasAovs()) throw std::logic_error("DeviceFilm::readAovs on a film without AOVs");
  AovImages aovs(width_, height_);
  albedo_.download(aovs.albedo.pixels.data(), albedo_.size());
  normal_.download(aovs.normal.pixels.data(), normal_.size());
  depth_.download(aovs.depth.data(), depth_.size());
  std::vector<Vec3> radiance(samples_.size() / sizeof(uint32_t));
  std::vector<float> squares(radiance.size()), oddLuminance(radiance.size());
  std::vector<uint32_t> oddSamples(radiance.size());
  radiance_.download(radiance.data(), radiance_.size());
  luminanceSquares_.download(squares.data(), luminanceSquares_.size());
  oddLuminance_.download(oddLuminance.data(), oddLuminance_.size());
  oddSamples_.download(oddSamples.data(), oddSamples_.size());
  const std::vector<uint32_t> samples = downloadSamples();
  for (size_t i = 0; i < samples.size(); ++i) {
    aovs.variance[i] = meanLuminanceVariance(radiance[i], squares[i], samples[i]);
    aovs.halvesVariance[i] = halvesVariance(radiance[i], oddLuminance[i], samples[i], oddSamples[i]);
    aovs.albedo.pixels[i] = filmMean(aovs.albedo.pixels[i], samples[i]);
    aovs.normal.pixels[i] = filmMean(aovs.normal.pixels[i], samples[i]);
    aovs.depth[i] = filmMean(aovs.depth[i], samples[i]);
  }
  aovs.emission = meanImage(emission_);
  return aovs;
}

FilmSums DeviceFilm::download() const {
  FilmSums f = FilmSums::zero(width_, height_, hasAovs());
  radiance_.download(f.radiance.data(), radiance_.size());
  emission_.download(f.emission.data(), emission_.size());
  samples_.download(f.samples.data(), samples_.size());
  if (hasAovs()) {
    albedo_.download(f.albedo.data(), albedo_.size());
    normal_.download(f.normal.data(), normal_.size());
    depth_.download(f.depth.data(), depth_.size());
    luminanceSquares_.download(f.luminanceSquares.data(), luminanceSquares_.size());
    oddLuminance_.download(f.oddLuminance.data(), oddLuminance_.size());
    oddSamples_.download(f.oddSamples.data(), oddSamples_.size());
  }
  return f;
}

void DeviceFilm::upload(const FilmSums& sums) {
  if (sums.width != width_ || sums.height != height_ || sums.hasAovs() != hasAovs())
    throw std::invalid_argument("DeviceFilm::upload: the sums have another size or AOVs");
  radiance_.upload(sums.radiance.data(), radiance_.size());
  emission_.upload(sums.emission.data(), emission_.size());
  samples_.upload(sums.samples.data(), samples_.size());
  if (hasAovs()) {
    albedo_.upload(sums.albedo.data(), albedo_.size());
    normal_.upload(sums.normal.data(), normal_.size());
    depth_.upload(sums.depth.data(), depth_.size());
    luminanceSquares_.upload(sums.luminanceSquares.data(), luminanceSquares_.size());
    oddLuminance_.upload(sums.oddLuminance.data(), oddLuminance_.size());
    oddSamples_.upload(sums.oddSamples.data(), oddSamples_.size());
  }
}

}  // namespace candela::optix
