// Whether render takes an image for one whose camera sees no light: fewer than 1% of its pixels visible once tone
// mapped as the PNG is written.
#include <gtest/gtest.h>

#include "image/visible_pixels.h"

namespace candela {
namespace {

Image imageWithLitPixels(uint32_t lit, float radiance) {
  Image image(100, 100);
  for (uint32_t i = 0; i < lit; ++i) image.pixels[i * 37 % image.pixels.size()] = {radiance, 0, 0};
  return image;
}

TEST(VisiblePixels, CountsThePixelsThatAreNotBlackOnceToneMapped) {
  const DisplaySettings display;
  EXPECT_EQ(visiblePixelFraction(imageWithLitPixels(0, 1.0f), display), 0.0);
  EXPECT_EQ(visiblePixelFraction(imageWithLitPixels(250, 1.0f), display), 0.025);
  // Radiance that quantises to 0 of 255 is black; two stops of exposure make it visible.
  EXPECT_EQ(visiblePixelFraction(imageWithLitPixels(250, 1e-5f), display), 0.0);
  DisplaySettings brighter;
  brighter.exposure = 8.0f;
  EXPECT_EQ(visiblePixelFraction(imageWithLitPixels(250, 1e-5f), brighter), 0.025);
}

TEST(VisiblePixels, AnImageIsUnlitBelowOnePercent) {
  const DisplaySettings display;
  EXPECT_TRUE(looksUnlit(imageWithLitPixels(0, 1.0f), display));
  EXPECT_TRUE(looksUnlit(imageWithLitPixels(99, 1.0f), display));
  EXPECT_FALSE(looksUnlit(imageWithLitPixels(100, 1.0f), display));
  EXPECT_FALSE(looksUnlit(imageWithLitPixels(10000, 0.01f), display));  // dim but visible everywhere
}

}  // namespace
}  // namespace candela
