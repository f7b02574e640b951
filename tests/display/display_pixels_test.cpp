// Display frames on the CPU (image/display_pixels.h): the bytes of toneMap and displayByte, the sRGB byte table
// that replaces powf, and the box-mean downscaling.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

#include "image/display_pixels.h"
#include "image/image.h"

namespace candela {
namespace {

uint32_t bitsOf(float f) {
  uint32_t bits;
  std::memcpy(&bits, &f, sizeof bits);
  return bits;
}

float floatOf(uint32_t bits) {
  float f;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}

uint8_t powfByte(float t) { return displayByte(linearToSrgb(t)); }

// The reference: what the serve page's frames were made of, toneMap and displayByte per pixel.
std::vector<uint8_t> referenceBytes(const Image& image, const DisplaySettings& display) {
  std::vector<uint8_t> bytes;
  for (const Vec3& p : image.pixels) {
    const Vec3 c = toneMap(p, display.exposure, display.toneMapper);
    bytes.insert(bytes.end(), {displayByte(c.x), displayByte(c.y), displayByte(c.z)});
  }
  return bytes;
}

std::vector<uint8_t> displayBytes(const Image& image, const DisplaySettings& display, uint32_t divisor) {
  const DisplaySize size = displaySize(image.width, image.height, divisor);
  std::vector<uint8_t> bytes(size_t(size.width) * size.height * 3);
  writeDisplayPixels({image.pixels.data(), nullptr, image.width, image.height}, display, divisor, bytes.data());
  return bytes;
}

// The byte changes only at the table's thresholds; the table must agree with powf wherever t lands. Checked here
// at every float within 2^14 representations of each threshold (where powf's rounding could reorder bytes),
// at both ends of every bucket, and at a million random values.
TEST(SrgbByteTable, GivesPowfsBytes) {
  const SrgbByteTable& table = srgbByteTable();
  for (int b = 1; b < 256; ++b) {
    const uint32_t threshold = bitsOf(table.threshold[b]);
    EXPECT_EQ(powfByte(table.threshold[b]), b);
    EXPECT_EQ(powfByte(floatOf(threshold - 1)), b - 1);
    for (uint32_t bits = threshold - (1u << 14); bits <= threshold + (1u << 14); ++bits) {
      const float t = floatOf(std::min(bits, SrgbByteTable::kOneBits));
      ASSERT_EQ(srgbByte(table, t), powfByte(t)) << "t = " << t;
    }
  }
  for (uint32_t bucket = 0; bucket < SrgbByteTable::kBuckets; ++bucket) {
    const uint32_t first = bucket << SrgbByteTable::kBucketShift;
    const uint32_t last = std::min(first + (1u << SrgbByteTable::kBucketShift) - 1, SrgbByteTable::kOneBits);
    ASSERT_EQ(srgbByte(table, floatOf(first)), powfByte(floatOf(first)));
    ASSERT_EQ(srgbByte(table, floatOf(last)), powfByte(floatOf(last)));
  }
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int i = 0; i < 1000000; ++i) {
    const float t = u(rng);
    ASSERT_EQ(srgbByte(table, t), powfByte(t)) << "t = " << t;
  }
  EXPECT_EQ(srgbByte(table, 0.0f), 0);
  EXPECT_EQ(srgbByte(table, 1.0f), 255);
}

// Linear radiance of every kind a film or a filter can give, and some it should not: zeros, tiny and huge values,
// negatives, infinities and NaN.
Image awkwardImage() {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> logValue(-7.0f, 4.0f);
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  const float specials[] = {0.0f, -0.0f, 1e-40f, 1e-30f, -1.0f, 0.5f, 1.0f, 3e38f, inf, -inf, nan};
  Image image(97, 61);
  size_t i = 0;
  for (Vec3& p : image.pixels) {
    auto channel = [&] {
      ++i;
      return i % 13 == 0 ? specials[(i / 13) % std::size(specials)] : std::pow(10.0f, logValue(rng));
    };
    p = {channel(), channel(), channel()};
  }
  return image;
}

TEST(DisplayPixels, AreToneMapsBytes) {
  const Image image = awkwardImage();
  for (ToneMapper mapper : {ToneMapper::AcesFilmic, ToneMapper::Clamp, ToneMapper::Reinhard})
    for (float exposure : {0.0f, -3.0f, 2.5f, 1.37f, -20.0f, 130.0f}) {
      const DisplaySettings display{exposure, mapper};
      EXPECT_EQ(displayBytes(image, display, 1), referenceBytes(image, display))
          << toneMapperName(mapper) << " at exposure " << exposure;
    }
}

TEST(DisplayPixels, OfAFilmsSumsAreThoseOfItsMeans) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0.0f, 50.0f);
  const uint32_t w = 40, h = 30;
  std::vector<Vec3> sums(w * h);
  std::vector<uint32_t> samples(w * h);
  Image means(w, h);
  for (size_t i = 0; i < sums.size(); ++i) {
    sums[i] = {u(rng), u(rng), u(rng)};
    samples[i] = uint32_t(i % 7);  // some pixels without a sample
    means.pixels[i] = filmMean(sums[i], samples[i]);
  }
  for (uint32_t divisor : {1u, 2u, 3u}) {
    const DisplaySize size = displaySize(w, h, divisor);
    std::vector<uint8_t> fromSums(size_t(size.width) * size.height * 3);
    writeDisplayPixels({sums.data(), samples.data(), w, h}, DisplaySettings{}, divisor, fromSums.data());
    EXPECT_EQ(fromSums, displayBytes(means, DisplaySettings{}, divisor)) << "divisor " << divisor;
  }
}

// A frame downscaled by 2 or 4 from an image of constant blocks is the frame of the image of the blocks: their
// means are exact in floats. The columns and rows past the last whole block are left out.
TEST(DisplayPixels, DownscaleToTheBlocksMeans) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(0.0f, 3.0f);
  for (uint32_t divisor : {2u, 4u}) {
    const Image small = [&] {
      Image s(23, 17);
      for (Vec3& p : s.pixels) p = {u(rng), u(rng), u(rng)};
      return s;
    }();
    Image large(small.width * divisor + divisor - 1, small.height * divisor + 1);
    for (uint32_t y = 0; y < large.height; ++y)
      for (uint32_t x = 0; x < large.width; ++x)
        large.at(x, y) = x / divisor < small.width && y / divisor < small.height ? small.at(x / divisor, y / divisor)
                                                                                 : Vec3{1e6f, 1e6f, 1e6f};
    const DisplaySize size = displaySize(large.width, large.height, divisor);
    EXPECT_EQ(size.width, small.width);
    EXPECT_EQ(size.height, small.height);
    EXPECT_EQ(displayBytes(large, DisplaySettings{}, divisor), displayBytes(small, DisplaySettings{}, 1));
  }
}

// With any divisor, each pixel is the box mean of its block, up to the rounding of the float sum: within one byte
// of the block's mean computed in double precision.
TEST(DisplayPixels, DownscaleToTheBoxMean) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<float> u(0.0f, 2.0f);
  Image image(50, 32);
  for (Vec3& p : image.pixels) p = {u(rng), u(rng), u(rng)};
  const uint32_t divisor = 3;
  const DisplaySize size = displaySize(image.width, image.height, divisor);
  ASSERT_EQ(size.width, 16u);
  ASSERT_EQ(size.height, 10u);
  Image means(size.width, size.height);
  for (uint32_t y = 0; y < size.height; ++y)
    for (uint32_t x = 0; x < size.width; ++x) {
      double sum[3] = {0, 0, 0};
      for (uint32_t dy = 0; dy < divisor; ++dy)
        for (uint32_t dx = 0; dx < divisor; ++dx)
          for (int c = 0; c < 3; ++c) sum[c] += image.at(x * divisor + dx, y * divisor + dy)[c];
      means.at(x, y) = {float(sum[0] / 9), float(sum[1] / 9), float(sum[2] / 9)};
    }
  const std::vector<uint8_t> downscaled = displayBytes(image, DisplaySettings{}, divisor);
  const std::vector<uint8_t> reference = referenceBytes(means, DisplaySettings{});
  ASSERT_EQ(downscaled.size(), reference.size());
  for (size_t i = 0; i < reference.size(); ++i) EXPECT_LE(std::abs(int(downscaled[i]) - int(reference[i])), 1);
}

TEST(DisplayPixels, RefuseDivisorsThatLeaveNoPixel) {
  EXPECT_THROW(displaySize(64, 48, 0), std::invalid_argument);
  EXPECT_THROW(displaySize(64, 48, 49), std::invalid_argument);
  EXPECT_EQ(displaySize(64, 48, 48).width, 1u);
}

}  // namespace
}  // namespace candela
