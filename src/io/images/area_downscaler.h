#pragma once
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <stdexcept>
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
// row by row, so a large image is never held whole. At the source's own size it copies. Images have 1 to 4
// channels.
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
    if (channels < 1 || channels > 4) throw std::invalid_argument("an image has 1 to 4 channels");
    if (copies()) return;
    sums_.assign(size_t(targetWidth) * channels, 0);
    columnSums_.assign(size_t(sourceWidth) * channels, 0);
    // The source columns of target column x are [columnStart_[x], columnStart_[x + 1]).
    columnStart_.assign(targetWidth + 1, sourceWidth);
    for (uint32_t x = sourceWidth; x-- > 0;) columnStart_[uint64_t(x) * targetWidth / sourceWidth] = x;
    columnScale_.resize(targetWidth);
    for (uint32_t x = 0; x < targetWidth; ++x) columnScale_[x] = 1.0 / double(columnStart_[x + 1] - columnStart_[x]);
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
    const size_t samples = size_t(sourceWidth_) * channels_;
    ColumnSum* columnSums = columnSums_.data();
    for (size_t i = 0; i < samples; ++i) columnSums[i] += ColumnSum(row[i]);
    if (++rowsInColumnSums_ == kMaxRowsInColumnSums) addColumnSums();
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
  // Integer samples add up exactly, and faster, as integers.
  using Sum = std::conditional_t<std::is_integral_v<Sample>, uint64_t, double>;
  using SignedSum = std::conditional_t<std::is_integral_v<Sample>, int64_t, double>;
  // 8-bit samples add up per source column in 32 bits (twice as many per vector), which hold 2^24 rows of them.
  static constexpr bool kBytes = std::is_integral_v<Sample> && sizeof(Sample) == 1;
  using ColumnSum = std::conditional_t<kBytes, uint32_t, Sum>;
  static constexpr uint32_t kMaxRowsInColumnSums = kBytes ? (1u << 24) : ~0u;

  bool copies() const { return sourceWidth_ == targetWidth_ && sourceHeight_ == targetHeight_; }

  // Rows are first added up per source column (addRow), which vectorises; once per target row (emitRow), or when
  // the column sums could overflow (addColumnSums), each target column adds up its run of source columns, its
  // channels in registers. The decoders of large images spend most of their own time in these loops, which
  // read the vectors through local pointers: a store of 8-bit samples may alias anything, and would make the
  // compiler load each vector's pointer again after it.
  template <uint32_t kChannels>
  static void sumRun(const uint32_t* columnStart, const ColumnSum* columnSums, uint32_t x, Sum (&run)[kChannels]) {
    for (uint32_t s = columnStart[x], end = columnStart[x + 1]; s < end; ++s)
      for (uint32_t c = 0; c < kChannels; ++c) run[c] += Sum(columnSums[size_t(s) * kChannels + c]);
  }

  template <class Step>
  void withChannels(const Step& step) {
    switch (channels_) {
      case 1: step(std::integral_constant<uint32_t, 1>()); break;
      case 2: step(std::integral_constant<uint32_t, 2>()); break;
      case 3: step(std::integral_constant<uint32_t, 3>()); break;
      default: step(std::integral_constant<uint32_t, 4>()); break;
    }
    std::fill(columnSums_.begin(), columnSums_.end(), ColumnSum(0));
    rowsInColumnSums_ = 0;
  }

  void addColumnSums() {
    withChannels([&](auto channels) {
      constexpr uint32_t kChannels = decltype(channels)::value;
      for (uint32_t x = 0; x < targetWidth_; ++x) {
        Sum run[kChannels] = {};
        sumRun(columnStart_.data(), columnSums_.data(), x, run);
        for (uint32_t c = 0; c < kChannels; ++c) sums_[size_t(x) * kChannels + c] += run[c];
      }
    });
  }

  void emitRow() {
    withChannels([&](auto channels) {
      constexpr uint32_t kChannels = decltype(channels)::value;
      Sample* out = &pixels_[size_t(targetRow_) * targetWidth_ * kChannels];
      const double rowScale = 1.0 / double(rowsInSums_);
      const uint32_t* columnStart = columnStart_.data();
      const ColumnSum* columnSums = columnSums_.data();
      const double* columnScale = columnScale_.data();
      Sum* sums = sums_.data();
      const uint32_t width = targetWidth_;
      for (uint32_t x = 0; x < width; ++x) {
        Sum run[kChannels];
        for (uint32_t c = 0; c < kChannels; ++c) run[c] = std::exchange(sums[size_t(x) * kChannels + c], Sum(0));
        sumRun(columnStart, columnSums, x, run);
        const double scale = columnScale[x] * rowScale;
        for (uint32_t c = 0; c < kChannels; ++c) {
          // Integer samples round to nearest; the mean of integers in range stays in range. (A sum converts
          // from a signed integer, which is one instruction: it is far below 2^63.)
          const double mean = double(SignedSum(run[c])) * scale;
          out[size_t(x) * kChannels + c] = std::is_integral_v<Sample> ? Sample(mean + 0.5) : Sample(mean);
        }
      }
    });
    rowsInSums_ = 0;
  }

  uint32_t sourceWidth_, sourceHeight_, targetWidth_, targetHeight_, channels_;
  std::vector<Sample> pixels_;
  std::vector<Sum> sums_;
  std::vector<ColumnSum> columnSums_;
  uint32_t rowsInColumnSums_ = 0;
  std::vector<uint32_t> columnStart_;
  std::vector<double> columnScale_;  // 1 / the source columns of each target column
  uint32_t sourceRow_ = 0;
  uint32_t targetRow_ = 0;
  uint32_t rowsInSums_ = 0;
};

}  // namespace candela
