#include <gtest/gtest.h>

#include <cstdlib>
#include <utility>

#include "app/serve/frame_encoding.h"
#include "io/images/image_decoding.h"

namespace candela {
namespace {

Image gradient() {
  Image image(64, 32);
  for (uint32_t y = 0; y < image.height; ++y)
    for (uint32_t x = 0; x < image.width; ++x) image.at(x, y) = Vec3(float(x) / 64.0f, float(y) / 32.0f, 0.25f);
  return image;
}

TEST(FrameEncoding, TheDisplayImageIsToneMappedLikeThePng) {
  DisplaySettings display;
  display.toneMapper = ToneMapper::Clamp;
  const DisplayImage d = displayImage(gradient(), display);
  ASSERT_EQ(d.rgb.size(), 64u * 32u * 3u);
  EXPECT_EQ(d.rgb[2], uint8_t(linearToSrgb(0.25f) * 255.0f + 0.5f));
  display.exposure = -3.0f;
  EXPECT_LT(displayImage(gradient(), display).rgb[2], d.rgb[2]);
}

TEST(FrameEncoding, PngDecodesToTheImage) {
  const DisplayImage d = displayImage(gradient(), DisplaySettings());
  const std::string png = encodePng(d);
  const Texture decoded = decodeImage("frame", reinterpret_cast<const uint8_t*>(png.data()), png.size(), /*srgb=*/true);
  ASSERT_EQ(decoded.channels, 4u);
  EXPECT_EQ(decoded.width, 64u);
  EXPECT_EQ(decoded.height, 32u);
  for (size_t i = 0; i < d.rgb.size(); ++i) ASSERT_EQ(decoded.bytes[i / 3 * 4 + i % 3], d.rgb[i]) << i;
}

}  // namespace
}  // namespace candela
