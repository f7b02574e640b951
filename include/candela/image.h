#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>

namespace candela::api {

// Linear float pixels, row-major, top row first, `channels` floats per pixel (3 for colours and normals, 1 for
// depth). Copies share the pixels: an image handed out by render() is never copied on its way to the caller.
class Image {
 public:
  Image() = default;
  Image(uint32_t width, uint32_t height, uint32_t channels, std::shared_ptr<float> pixels)
      : width_(width), height_(height), channels_(channels), pixels_(std::move(pixels)) {}

  uint32_t width() const { return width_; }
  uint32_t height() const { return height_; }
  uint32_t channels() const { return channels_; }
  size_t size() const { return size_t(width_) * height_ * channels_; }  // floats
  float* data() const { return pixels_.get(); }
  float at(uint32_t x, uint32_t y, uint32_t channel) const {
    return pixels_.get()[(size_t(y) * width_ + x) * channels_ + channel];
  }

 private:
  uint32_t width_ = 0, height_ = 0, channels_ = 0;
  std::shared_ptr<float> pixels_;
};

}  // namespace candela::api
