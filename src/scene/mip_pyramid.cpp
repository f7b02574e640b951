#include "scene/mip_pyramid.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "kernel/texture.h"

namespace candela {

namespace {

// The source texels one target texel covers along an axis, and the fraction of the target each contributes.
struct Taps {
  uint32_t first = 0;
  uint32_t count = 0;
  std::array<float, 4> weights{};  // a halving step spans at most 3 source texels, so touches at most 4
};

std::vector<Taps> axisTaps(uint32_t source, uint32_t target) {
  std::vector<Taps> taps(target);
  const double scale = double(source) / double(target);
  for (uint32_t i = 0; i < target; ++i) {
    const double lo = i * scale, hi = (i + 1) * scale;
    Taps& t = taps[i];
    t.first = uint32_t(std::floor(lo));
    for (uint32_t s = t.first; s < source && double(s) < hi && t.count < t.weights.size(); ++s) {
      const double overlap = std::min(hi, double(s + 1)) - std::max(lo, double(s));
      t.weights[t.count++] = float(std::max(overlap, 0.0) / scale);
    }
  }
  return taps;
}

// Which channel of a texel is alpha, or `channels` when none is (as fetchTexel reads them).
uint32_t alphaChannel(uint32_t channels) { return channels == 4 ? 3u : (channels == 2 ? 1u : channels); }

// One step down from a source whose rows `decodeRow(y, out)` writes as linear values: each target row is built
// from the few source rows under it, filtered across as they are needed, so the source is never held whole in
// floats (an 8-bit texture's finest level is read straight from its bytes). Target rows are independent and are
// computed in parallel. The channel count is a constant, so that a texel's channels stay in registers.
template <uint32_t channels, class DecodeRow>
std::vector<float> downsampleRowsOf(const DecodeRow& decodeRow, uint32_t sourceWidth, uint32_t sourceHeight,
                                    uint32_t targetWidth, uint32_t targetHeight) {
  const std::vector<Taps> columns = axisTaps(sourceWidth, targetWidth), rows = axisTaps(sourceHeight, targetHeight);
  std::vector<float> target(size_t(targetWidth) * targetHeight * channels, 0.0f);
  tbb::parallel_for(tbb::blocked_range<uint32_t>(0, targetHeight), [&](const tbb::blocked_range<uint32_t>& range) {
    std::vector<float> sourceRow(size_t(sourceWidth) * channels), across(size_t(targetWidth) * channels);
    for (uint32_t y = range.begin(); y < range.end(); ++y) {
      const Taps& down = rows[y];
      float* out = &target[size_t(y) * targetWidth * channels];
      for (uint32_t k = 0; k < down.count; ++k) {
        decodeRow(down.first + k, sourceRow.data());
        for (uint32_t x = 0; x < targetWidth; ++x) {
          const Taps& t = columns[x];
          float texel[channels] = {};
          for (uint32_t j = 0; j < t.count; ++j) {
            const float* in = &sourceRow[size_t(t.first + j) * channels];
            for (uint32_t c = 0; c < channels; ++c) texel[c] += t.weights[j] * in[c];
          }
          std::copy_n(texel, channels, &across[size_t(x) * channels]);
        }
        for (size_t i = 0; i < across.size(); ++i) out[i] += down.weights[k] * across[i];
      }
    }
  });
  return target;
}

template <class DecodeRow>
std::vector<float> downsampleRows(const DecodeRow& decodeRow, uint32_t sourceWidth, uint32_t sourceHeight,
                                  uint32_t targetWidth, uint32_t targetHeight, uint32_t channels) {
  switch (channels) {
    case 1: return downsampleRowsOf<1>(decodeRow, sourceWidth, sourceHeight, targetWidth, targetHeight);
    case 2: return downsampleRowsOf<2>(decodeRow, sourceWidth, sourceHeight, targetWidth, targetHeight);
    case 3: return downsampleRowsOf<3>(decodeRow, sourceWidth, sourceHeight, targetWidth, targetHeight);
    case 4: return downsampleRowsOf<4>(decodeRow, sourceWidth, sourceHeight, targetWidth, targetHeight);
    default: throw std::invalid_argument("a texture has 1 to 4 channels");
  }
}

// Calls `emit(level, values)` with each level below the finest as linear values, the finest read through
// `decodeRow`.
template <class DecodeRow, class Emit>
void forEachCoarserLevel(const DecodeRow& decodeRow, uint32_t width, uint32_t height, uint32_t channels, Emit&& emit) {
  const uint32_t levels = fullMipLevelCount(width, height);
  if (levels < 2) return;
  std::vector<float> level =
      downsampleRows(decodeRow, width, height, mipLevelSize(width, 1), mipLevelSize(height, 1), channels);
  emit(level);
  for (uint32_t l = 2; l < levels; ++l) {
    level = downsampleLevel(level, mipLevelSize(width, l - 1), mipLevelSize(height, l - 1), mipLevelSize(width, l),
                            mipLevelSize(height, l), channels);
    emit(level);
  }
}

// 8-bit sRGB by table: decoding is a lookup; encoding finds the step whose range of linear values (between the
// values halfway to its neighbours) holds the value, which is the step that rounding the encoded value would
// give. A table over the linear range gives the step at each bin's start; the few steps within a bin are then
// walked.
struct SrgbTables {
  static constexpr int kBins = 16384;
  std::array<float, 256> decode{};
  std::array<float, 255> halfSteps{};
  std::vector<uint8_t> stepAtBin = std::vector<uint8_t>(kBins + 1);
  SrgbTables() {
    for (int i = 0; i < 256; ++i) decode[i] = srgbToLinear(float(i) / 255.0f);
    for (int i = 0; i < 255; ++i) halfSteps[i] = srgbToLinear((float(i) + 0.5f) / 255.0f);
    for (int b = 0; b <= kBins; ++b) stepAtBin[b] = walk(0, float(b) / kBins);
  }
  uint8_t walk(uint8_t step, float linear) const {
    while (step < 255 && linear >= halfSteps[step]) ++step;
    return step;
  }
  uint8_t encode(float linear) const {
    const float v = std::clamp(linear, 0.0f, 1.0f);
    return walk(stepAtBin[int(v * kBins)], v);
  }
};

uint8_t toUnorm8(float v) { return uint8_t(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f); }

}  // namespace

size_t coarserMipLevelsSize(uint32_t width, uint32_t height, uint32_t channels) {
  size_t values = 0;
  for (uint32_t l = 1, levels = fullMipLevelCount(width, height); l < levels; ++l)
    values += size_t(mipLevelSize(width, l)) * mipLevelSize(height, l) * channels;
  return values;
}

std::vector<float> downsampleLevel(const std::vector<float>& source, uint32_t sourceWidth, uint32_t sourceHeight,
                                   uint32_t targetWidth, uint32_t targetHeight, uint32_t channels) {
  const size_t rowLength = size_t(sourceWidth) * channels;
  auto decodeRow = [&](uint32_t y, float* out) { std::copy_n(&source[y * rowLength], rowLength, out); };
  return downsampleRows(decodeRow, sourceWidth, sourceHeight, targetWidth, targetHeight, channels);
}

void writeCoarserMipLevels(const uint8_t* level0, uint32_t width, uint32_t height, uint32_t channels, bool srgb,
                           uint8_t* out) {
  static const SrgbTables tables;
  const uint32_t alpha = alphaChannel(channels);
  const size_t rowLength = size_t(width) * channels;
  // Each byte of a row decodes by its channel's table: sRGB, or linear for alpha and non-colour data.
  std::array<float, 256> linear{};
  for (int i = 0; i < 256; ++i) linear[size_t(i)] = float(i) / 255.0f;
  std::array<const float*, 4> tableOf{};
  for (uint32_t c = 0; c < 4; ++c) tableOf[c] = srgb && c != alpha ? tables.decode.data() : linear.data();
  auto decodeRow = [&](uint32_t y, float* row) {
    const uint8_t* in = level0 + y * rowLength;
    for (size_t texel = 0; texel < rowLength; texel += channels)
      for (uint32_t c = 0; c < channels; ++c) row[texel + c] = tableOf[c][in[texel + c]];
  };
  forEachCoarserLevel(decodeRow, width, height, channels, [&](const std::vector<float>& level) {
    // Through local copies: a byte store may alias anything, and would make the compiler load them again.
    const float* values = level.data();
    const size_t count = level.size();
    const uint32_t n = channels, alphaAt = alpha;
    const bool colour = srgb;
    uint8_t* bytes = out;
    for (size_t texel = 0; texel < count; texel += n)
      for (uint32_t c = 0; c < n; ++c)
        *bytes++ = colour && c != alphaAt ? tables.encode(values[texel + c]) : toUnorm8(values[texel + c]);
    out = bytes;
  });
}

void writeCoarserMipLevels(const float* level0, uint32_t width, uint32_t height, uint32_t channels, float* out) {
  const size_t rowLength = size_t(width) * channels;
  auto decodeRow = [&](uint32_t y, float* row) { std::copy_n(level0 + y * rowLength, rowLength, row); };
  forEachCoarserLevel(decodeRow, width, height, channels,
                      [&](const std::vector<float>& level) { out = std::copy(level.begin(), level.end(), out); });
}

}  // namespace candela
