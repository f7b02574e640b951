// The H.264 encoder's stream as the page's decoder needs it (video_decode.mjs decodes it in Chromium): Annex B
// access units, a key frame where one is due, the codec string of its SPS.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "io/video/h264_encoder.h"

namespace candela {
namespace {

std::vector<uint8_t> gradient(uint32_t width, uint32_t height, uint32_t shift) {
  std::vector<uint8_t> rgb(size_t(width) * height * 3);
  for (size_t i = 0; i < rgb.size(); ++i) rgb[i] = uint8_t((i / 3 % width + shift) * 255 / (width + shift));
  return rgb;
}

TEST(H264Encoder, KeyFramesWhereDueAndAnnexBAccessUnits) {
  H264Encoder encoder(2);
  const H264Settings settings;
  auto encode = [&](uint32_t width, uint32_t height, uint32_t shift, bool key) {
    const std::vector<uint8_t> rgb = gradient(width, height, shift);
    return encoder.encode(rgb.data(), width, height, settings, key);
  };
  const H264Frame first = encode(65, 37, 0, false);  // odd: coded as 66 x 38
  EXPECT_TRUE(first.key);
  EXPECT_EQ(first.width, 65u);
  EXPECT_EQ(first.height, 37u);
  EXPECT_TRUE(first.codec.size() == 11 && first.codec.rfind("avc1.", 0) == 0 &&
              first.codec.find_first_not_of("0123456789ABCDEF", 5) == std::string::npos)
      << first.codec;
  ASSERT_GE(first.bytes.size(), 5u);
  EXPECT_EQ(first.bytes.substr(0, 4), std::string("\0\0\0\1", 4));
  EXPECT_EQ(uint8_t(first.bytes[4]) & 0x1f, 7) << "a key frame starts with its SPS";
  const H264Frame next = encode(65, 37, 1, false);
  EXPECT_FALSE(next.key);
  EXPECT_EQ(next.codec, first.codec);
  EXPECT_TRUE(encode(65, 37, 2, true).key) << "asked for";
  EXPECT_FALSE(encode(65, 37, 3, false).key);
  EXPECT_TRUE(encode(64, 38, 3, false).key) << "a new size starts a new stream";
  EXPECT_THROW(encode(1, 38, 0, false), std::invalid_argument);
}

// Frames of noise, new every frame, which take all the rate the encoder allows.
class NoiseFrames {
 public:
  const std::vector<uint8_t>& next() {
    for (uint8_t& b : rgb_) b = uint8_t((state_ = state_ * 1664525u + 1013904223u) >> 24);
    return rgb_;
  }
  static constexpr uint32_t kWidth = 320, kHeight = 240;

 private:
  std::vector<uint8_t> rgb_ = std::vector<uint8_t>(size_t(kWidth) * kHeight * 3);
  uint32_t state_ = 1;
};

// The stream's rate in the second after `settings.framesPerSecond` frames encoded with `settings`, following
// `opening` frames encoded with `openedAt` (which open the stream).
double kilobitsPerSecond(const H264Settings& openedAt, uint32_t opening, const H264Settings& settings) {
  H264Encoder encoder(2);
  NoiseFrames noise;
  for (uint32_t frame = 0; frame < opening; ++frame)
    encoder.encode(noise.next().data(), NoiseFrames::kWidth, NoiseFrames::kHeight, openedAt, false);
  size_t bytes = 0;
  for (uint32_t frame = 0; frame < 2 * settings.framesPerSecond; ++frame) {
    const H264Frame encoded =
        encoder.encode(noise.next().data(), NoiseFrames::kWidth, NoiseFrames::kHeight, settings, false);
    if (frame >= settings.framesPerSecond) bytes += encoded.bytes.size();
  }
  return double(bytes) * 8.0 / 1000.0;
}

// The rate control keeps a noisy picture's frames near the rate it is given.
TEST(H264Encoder, TheRateStaysNearItsLimit) {
  H264Settings settings;
  settings.maxKilobitsPerSecond = 2000;
  settings.framesPerSecond = 30;
  const double rate = kilobitsPerSecond(settings, 0, settings);
  EXPECT_LT(rate, 1.5 * settings.maxKilobitsPerSecond);
  EXPECT_GT(rate, 0.3 * settings.maxKilobitsPerSecond) << "noise takes what the rate allows";
}

// A stream opened at 60 frames a second whose frames then come at 150 (or 20) keeps to the rate: x264 cannot
// change the frame rate it was opened with, so the limits follow the measured one.
TEST(H264Encoder, TheRateHoldsAtTheMeasuredFrameRate) {
  H264Settings opened;
  opened.maxKilobitsPerSecond = 2000;
  opened.framesPerSecond = 60;
  for (const uint32_t framesPerSecond : {150u, 20u}) {
    H264Settings measured = opened;
    measured.framesPerSecond = framesPerSecond;
    const double rate = kilobitsPerSecond(opened, 10, measured);
    EXPECT_LT(rate, 1.1 * opened.maxKilobitsPerSecond) << framesPerSecond << " frames a second";
    EXPECT_GT(rate, 0.5 * opened.maxKilobitsPerSecond) << framesPerSecond << " frames a second";
  }
}

}  // namespace
}  // namespace candela
