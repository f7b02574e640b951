// The window's GPU path against the CPU code it must agree with. Runs on an X display (CTest starts Xvfb).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "app/viewer/glfw_window.h"
#include "app/viewer/image_display.h"
#include "image/filters/bilateral.h"
#include "image/tonemap.h"

namespace candela {
namespace {

constexpr int kWindowWidth = 320;
constexpr int kWindowHeight = 200;

class GlDisplay : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    window_ = std::make_unique<GlfwWindow>(kWindowWidth, kWindowHeight, "candela display test");
    display_ = std::make_unique<ImageDisplay>();
  }
  static void TearDownTestSuite() {
    display_.reset();
    window_.reset();
  }
  static std::unique_ptr<GlfwWindow> window_;
  static std::unique_ptr<ImageDisplay> display_;
};
std::unique_ptr<GlfwWindow> GlDisplay::window_;
std::unique_ptr<ImageDisplay> GlDisplay::display_;

// Noise over [0, 1] with a hard step to 6 in the right half and a few fireflies, as a renderer's output has.
Image testImage(uint32_t w, uint32_t h) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  Image image(w, h);
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      Vec3 c{u(rng), u(rng), u(rng)};
      if (x > w / 2) c = c + Vec3{6.0f, 5.0f, 4.0f};
      if (u(rng) < 0.01f) c = c * 30.0f;
      image.at(x, y) = c;
    }
  return image;
}

// The largest difference relative to max(1, |expected|), over all channels.
double worstRelativeError(const Image& actual, const Image& expected) {
  double worst = 0.0;
  for (size_t i = 0; i < expected.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      double e = expected.pixels[i][c], a = actual.pixels[i][c];
      worst = std::max(worst, std::fabs(a - e) / std::max(1.0, std::fabs(e)));
    }
  return worst;
}

// Measured with Mesa's llvmpipe: at most 5e-7 (float32 sums over at most 121 taps, the GPU's exp()); a change of
// 2% in the range sigma moves the result by more than 1e-3 (checked below).
constexpr double kBilateralTolerance = 1e-5;

TEST_F(GlDisplay, BilateralPassMatchesTheCpuFilter) {
  const Image input = testImage(67, 53);  // odd sizes: the borders are not aligned with anything
  display_->upload(input);
  for (BilateralParams params :
       {BilateralParams{0, 1.0f, 0.1f}, BilateralParams{1, 1.0f, 0.1f}, BilateralParams{3, 2.0f, 0.5f},
        BilateralParams{5, 3.0f, 5.0f}, BilateralParams{2, 0.7f, 0.2f}}) {
    Image gpu = display_->bilateralOnGpu(params);
    Image cpu = bilateralFilter(input, params);
    ASSERT_EQ(gpu.width, cpu.width);
    ASSERT_EQ(gpu.height, cpu.height);
    double error = worstRelativeError(gpu, cpu);
    EXPECT_LE(error, kBilateralTolerance) << "radius " << params.radius << ", spatial sigma " << params.spatialSigma
                                          << ", range sigma " << params.rangeSigma;
    if (params.radius == 0) continue;
    BilateralParams off = params;
    off.rangeSigma *= 1.02f;
    EXPECT_GT(worstRelativeError(gpu, bilateralFilter(input, off)), kBilateralTolerance)
        << "the comparison cannot tell a 2% range-sigma change apart";
  }
}

// With the emission beside the image, the pass smooths only the rest and adds the emission back, as the CPU and
// CUDA filters do: a bright emitter (part of the image, as the backend's emission is) is not smeared over its
// neighbours. Without the emission apart the same pass differs by far more than the tolerance.
TEST_F(GlDisplay, BilateralPassKeepsTheEmissionApart) {
  Image input = testImage(67, 53);
  Image emission(input.width, input.height);
  for (uint32_t y = 10; y < 30; ++y)
    for (uint32_t x = 5; x < 25; ++x) {
      emission.at(x, y) = {40.0f, 30.0f, 20.0f};
      input.at(x, y) = input.at(x, y) + emission.at(x, y);
    }
  display_->upload(input, &emission);
  for (BilateralParams params : {BilateralParams{1, 1.0f, 0.1f}, BilateralParams{3, 2.0f, 5.0f}}) {
    const Image gpu = display_->bilateralOnGpu(params);
    EXPECT_LE(worstRelativeError(gpu, bilateralFilter(input, emission, params)), kBilateralTolerance)
        << "radius " << params.radius << ", range sigma " << params.rangeSigma;
    EXPECT_GT(worstRelativeError(gpu, bilateralFilter(input, params)), 1e-2)
        << "the emission made no difference at radius " << params.radius;
  }
  // An image uploaded without emission is filtered whole again.
  display_->upload(input);
  EXPECT_LE(worstRelativeError(display_->bilateralOnGpu(BilateralParams{}), bilateralFilter(input, BilateralParams{})),
            kBilateralTolerance);
}

std::vector<uint8_t> cpuDisplayBytes(const Image& image, float exposure, ToneMapper mapper) {
  std::vector<uint8_t> bytes;
  for (const Vec3& p : image.pixels) {
    Vec3 c = toneMap(p, exposure, mapper);
    for (float v : {c.x, c.y, c.z}) bytes.push_back(uint8_t(v * 255.0f + 0.5f));
  }
  return bytes;
}

// Draws into the window's back buffer and reads the image's pixels back, top row first.
std::vector<uint8_t> drawAndRead(ImageDisplay& display, const Image& image, const PostSettings& post) {
  const int w = int(image.width), h = int(image.height);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, kWindowWidth, kWindowHeight);
  glClearColor(1.0f, 0.0f, 1.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  display.draw(post, 0, kWindowHeight - h, w, h);  // the top-left corner of the window
  std::vector<uint8_t> bottomUp(size_t(w) * h * 3), topDown(bottomUp.size());
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, kWindowHeight - h, w, h, GL_RGB, GL_UNSIGNED_BYTE, bottomUp.data());
  for (int y = 0; y < h; ++y)
    std::copy_n(bottomUp.begin() + ptrdiff_t(h - 1 - y) * w * 3, w * 3, topDown.begin() + ptrdiff_t(y) * w * 3);
  return topDown;
}

int worstByteDifference(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
  int worst = 0;
  for (size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::abs(int(a[i]) - int(b[i])));
  return worst;
}

TEST_F(GlDisplay, ToneMappingMatchesTonemapH) {
  // Each row a different brightness (so an upside-down image fails), radiance from 2^-9 to 2^5 along x.
  Image image(256, 6);
  for (uint32_t y = 0; y < image.height; ++y)
    for (uint32_t x = 0; x < image.width; ++x) {
      float v = std::exp2(-9.0f + 14.0f * float(x) / 255.0f) * float(y + 1) / 3.0f;
      image.at(x, y) = {v, 0.5f * v, x == 0 ? 0.0f : 2.0f * v};
    }
  display_->upload(image);
  for (ToneMapper mapper : {ToneMapper::AcesFilmic, ToneMapper::Clamp, ToneMapper::Reinhard})
    for (float exposure : {-2.0f, 0.0f, 1.5f}) {
      PostSettings post;
      post.display = {exposure, mapper};
      std::vector<uint8_t> gpu = drawAndRead(*display_, image, post);
      // The GPU's pow() and its float-to-byte rounding may land one step away from the CPU's.
      EXPECT_LE(worstByteDifference(gpu, cpuDisplayBytes(image, exposure, mapper)), 1)
          << "tone mapper " << int(mapper) << ", exposure " << exposure;
      EXPECT_GT(worstByteDifference(gpu, cpuDisplayBytes(image, exposure + 0.05f, mapper)), 1)
          << "the comparison cannot tell a 0.05-stop exposure change apart";
    }
}

TEST_F(GlDisplay, BilateralThenToneMappingIsWhatTheWindowShows) {
  const Image input = testImage(64, 48);
  display_->upload(input);
  PostSettings post;
  post.bilateral = true;
  post.bilateralParams = {2, 1.5f, 0.3f};
  std::vector<uint8_t> gpu = drawAndRead(*display_, input, post);
  EXPECT_LE(worstByteDifference(gpu, cpuDisplayBytes(bilateralFilter(input, post.bilateralParams), 0.0f,
                                                     ToneMapper::AcesFilmic)),
            1);
  EXPECT_GT(worstByteDifference(gpu, cpuDisplayBytes(input, 0.0f, ToneMapper::AcesFilmic)), 1);
}

}  // namespace
}  // namespace candela
