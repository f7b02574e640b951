#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "image/filters/bilateral.h"

namespace candela {
namespace {

Image noiseImage(uint32_t w, uint32_t h, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  Image image(w, h);
  for (Vec3& p : image.pixels) p = {u(rng), u(rng), u(rng)};
  return image;
}

TEST(CpuBilateral, RadiusZeroIsTheIdentity) {
  Image in = noiseImage(13, 7, 1);
  Image out = bilateralFilter(in, {0, 1.0f, 0.1f});
  for (size_t i = 0; i < in.pixels.size(); ++i) EXPECT_EQ(out.pixels[i].x, in.pixels[i].x);
}

TEST(CpuBilateral, ConstantImageStaysConstantUpToTheBorders) {
  Image in(9, 6);
  for (Vec3& p : in.pixels) p = {0.3f, 2.0f, 7.5f};
  Image out = bilateralFilter(in, {4, 2.0f, 0.5f});
  for (const Vec3& p : out.pixels) {
    EXPECT_NEAR(p.x, 0.3f, 1e-6f);
    EXPECT_NEAR(p.y, 2.0f, 1e-6f);
    EXPECT_NEAR(p.z, 7.5f, 1e-5f);
  }
}

TEST(CpuBilateral, WideRangeSigmaIsAGaussianBlur) {
  Image in = noiseImage(21, 17, 2);
  const BilateralParams params{3, 1.5f, 1e6f};
  Image out = bilateralFilter(in, params);
  // An independent sum: the normalised Gaussian over the taps inside the image.
  for (int y = 0; y < 17; ++y)
    for (int x = 0; x < 21; ++x) {
      double sum = 0.0, weights = 0.0;
      for (int dy = -3; dy <= 3; ++dy)
        for (int dx = -3; dx <= 3; ++dx) {
          int qx = x + dx, qy = y + dy;
          if (qx < 0 || qy < 0 || qx >= 21 || qy >= 17) continue;
          double w = std::exp(-(dx * dx + dy * dy) / (2.0 * 1.5 * 1.5));
          sum += w * in.at(uint32_t(qx), uint32_t(qy)).y;
          weights += w;
        }
      EXPECT_NEAR(out.at(uint32_t(x), uint32_t(y)).y, sum / weights, 1e-5);
    }
}

TEST(CpuBilateral, NarrowRangeSigmaKeepsAnEdge) {
  Image in(16, 8);
  for (uint32_t y = 0; y < 8; ++y)
    for (uint32_t x = 0; x < 16; ++x) in.at(x, y) = x < 8 ? Vec3{0.1f, 0.1f, 0.1f} : Vec3{5.0f, 5.0f, 5.0f};
  Image kept = bilateralFilter(in, {3, 2.0f, 0.05f});
  Image blurred = bilateralFilter(in, {3, 2.0f, 100.0f});
  // Across the edge the weights are exp(-4.9^2 / (2 0.05^2)): nothing leaks.
  EXPECT_FLOAT_EQ(kept.at(7, 4).x, 0.1f);
  EXPECT_FLOAT_EQ(kept.at(8, 4).x, 5.0f);
  EXPECT_GT(blurred.at(7, 4).x, 1.0f);
  EXPECT_LT(blurred.at(8, 4).x, 4.0f);
}

TEST(CpuBilateral, RejectsBadParameters) {
  Image in(4, 4);
  EXPECT_THROW(bilateralFilter(in, {-1, 1.0f, 1.0f}), std::invalid_argument);
  EXPECT_THROW(bilateralFilter(in, {kMaxBilateralRadius + 1, 1.0f, 1.0f}), std::invalid_argument);
  EXPECT_THROW(bilateralFilter(in, {2, 0.0f, 1.0f}), std::invalid_argument);
  EXPECT_THROW(bilateralFilter(in, {2, 1.0f, -1.0f}), std::invalid_argument);
  EXPECT_THROW(bilateralFilter(in, {2, 1.0f, NAN}), std::invalid_argument);
}

}  // namespace
}  // namespace candela
