#pragma once
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <utility>
#include <vector>

namespace candela {

// The largest size of about the same aspect ratio as width x height whose sides are at most maxSide (the longer
// side becomes maxSide exactly, the other is rounded down, never below 1); the size itself when it fits.
inline std::pair<uint32_t, uint32_t> sizeWithin(uint32_t width, uint32_t height, uint32_t maxSide) {
  if (width >= height && width > maxSide)
    return {maxSide, uint32_t(std::max<uint64_t>(1, uint64_t(height) * maxSide / width))};
  if (height > width && height > maxSide)
    return {uint32_t(std::max<uint64_t>(1, uint64_t(width) * maxSide / height)), maxSide};
  return {width, height};
}

// Takes an image's rows top to bottom and keeps a smaller image: each target pixel is the mean of the source
// pixels that fall in it (source pixel (x, y) falls in target pixel (x * tw / sw, y * th / sh)). Decoders feed it
// row by row, so a large image is never held whole. At the source's own size it copies.
template <typename Sample>
class AreaDownscaler {
 public:
  AreaDownscaler(uint32_t sourceWidth, uint32_t sourceHeight, uint32_t targetWidth, uint32_t targetHeight,
                 uint32_t channels)
      : sourceWidth_(sourceWidth),
        sourceHeight_(sourceHeight),
        targetWidth_(targetWidth),
        targetHeight_(targetHeight),
        channels_(channels),
        pixels_(size_t(targetWidth) * targetHeight * channels) {
    if (copies()) return;
    sums_.assign(size_t(targetWidth) * channels, 0);
    columnOf_.resize(sourceWidth);
    columnCounts_.assign(targetWidth, 0);
    for (uint32_t x = 0; x < sourceWidth; ++x) {
      columnOf_[x] = uint32_t(uint64_t(x) * targetWidth / sourceWidth);
      ++columnCounts_[columnOf_[x]];
    }
  }

  // The next source row: sourceWidth * channels samples.
  void addRow(const Sample* row) {
    if (copies()) {
      std::memcpy(&pixels_[size_t(sourceRow_++) * sourceWidth_ * channels_], row,
                  size_t(sourceWidth_) * channels_ * sizeof(Sample));
      return;
    }
    const uint32_t target = uint32_t(uint64_t(sourceRow_) * targetHeight_ / sourceHeight_);
    if (target != targetRow_) emitRow();
    targetRow_ = target;
    for (uint32_t x = 0; x < sourceWidth_; ++x)
      for (uint32_t c = 0; c < channels_; ++c)
        sums_[size_t(columnOf_[x]) * channels_ + c] += Sum(row[size_t(x) * channels_ + c]);
    ++rowsInSums_;
    ++sourceRow_;
  }

  uint32_t targetWidth() const { return targetWidth_; }
  uint32_t targetHeight() const { return targetHeight_; }
  uint32_t channels() const { return channels_; }

  // The target image, once every source row has been added.
  std::vector<Sample> finish() {
    if (!copies() && rowsInSums_ > 0) emitRow();
    return std::move(pixels_);
  }

 private:
  bool copies() const { return sourceWidth_ == targetWidth_ && sourceHeight_ == targetHeight_; }

  void emitRow() {
    Sample* out = &pixels_[size_t(targetRow_) * targetWidth_ * channels_];
    for (uint32_t x = 0; x < targetWidth_; ++x)
      for (uint32_t c = 0; c < channels_; ++c) {
        Sum& sum = sums_[size_t(x) * channels_ + c];
        const double mean = double(sum) / (double(columnCounts_[x]) * rowsInSums_);
        // Integer samples round to nearest; the mean of integers in range stays in range.
        out[size_t(x) * channels_ + c] = std::is_integral_v<Sample> ? Sample(mean + 0.5) : Sample(mean);
        sum = 0;
      }
    rowsInSums_ = 0;
  }

  uint32_t sourceWidth_, sourceHeight_, targetWidth_, targetHeight_, channels_;
  std::vector<Sample> pixels_;
  // Integer samples add up exactly, and faster, as integers.
  using Sum = std::conditional_t<std::is_integral_v<Sample>, uint64_t, double>;
  std::vector<Sum> sums_;
  std::vector<uint32_t> columnOf_;
  std::vector<uint32_t> columnCounts_;
  uint32_t sourceRow_ = 0;
  uint32_t targetRow_ = 0;
  uint32_t rowsInSums_ = 0;
};

}  // namespace candela
