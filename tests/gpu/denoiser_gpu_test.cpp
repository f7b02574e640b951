// The OptiX AI denoiser: where the driver has its weights, a denoised image is closer to a converged one than
// the noisy input; where it has not (OptiX error 7990), it says so in one sentence.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "backends/optix/optix_denoiser.h"
#include "gpu_render.h"
#include "support/scene_edits.h"

namespace candela {
namespace {

Image renderCornellBox(uint32_t seed, uint32_t spp) {
  auto backend = test::makeBackend<OptixBackend>(makeCornellBox(), test::squareImage(128, seed));
  backend->render(spp);
  return backend->readImage();
}

// A 4-spp Cornell box with the AOVs that guide the denoiser.
struct GuidedRender {
  Image image;
  AovImages aovs;
};
GuidedRender renderWithGuides(uint32_t size) {
  auto backend = test::makeBackend<OptixBackend>(makeCornellBox(), test::squareImage(size, 1));
  backend->setAovsEnabled(true);
  backend->render(4);
  return {backend->readImage(), backend->readAovs()};
}

// Mean over pixels and channels of (a - b)^2 / (b^2 + 1e-2), the usual relative MSE.
double relativeMse(const Image& a, const Image& b) {
  double sum = 0.0;
  for (size_t i = 0; i < a.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      double d = double(a.pixels[i][c]) - b.pixels[i][c];
      sum += d * d / (double(b.pixels[i][c]) * b.pixels[i][c] + 1e-2);
    }
  return sum / double(3 * a.pixels.size());
}

TEST(GpuDenoiser, DenoisesOrSaysWhyNot) {
  Image noisy = renderCornellBox(1, 4);
  Image reference = renderCornellBox(2, 4096);
  Image denoised;
  try {
    denoised = denoiseWithOptix(noisy);
  } catch (const std::runtime_error& e) {
    std::string message = e.what();
    EXPECT_NE(message.find("OptiX error 7990"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << "one sentence, one line";
    GTEST_SKIP() << "no denoiser weights in this driver: " << message;
  }
  ASSERT_EQ(denoised.width, noisy.width);
  ASSERT_EQ(denoised.height, noisy.height);
  for (Vec3 p : denoised.pixels) ASSERT_TRUE(isFinite(p));
  EXPECT_LT(relativeMse(denoised, reference), 0.5 * relativeMse(noisy, reference));
}

// With the albedo and normal guides from the backend's AOVs, as `candela render --denoise optix` feeds them.
TEST(GpuDenoiser, DenoisesWithGuidesOrSaysWhyNot) {
  const auto [noisy, aovs] = renderWithGuides(128);
  Image denoised;
  try {
    denoised = denoiseWithOptix(noisy, {&aovs.albedo, &aovs.normal});
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("OptiX error 7990"), std::string::npos) << e.what();
    GTEST_SKIP() << "no denoiser weights in this driver: " << e.what();
  }
  const Image reference = renderCornellBox(2, 4096);
  for (Vec3 p : denoised.pixels) ASSERT_TRUE(isFinite(p));
  EXPECT_LT(relativeMse(denoised, reference), 0.5 * relativeMse(noisy, reference));
}

// The viewer keeps one denoiser across frames and window sizes: each image must come out as a denoiser made for
// it alone would give it.
TEST(GpuDenoiser, AKeptDenoiserGivesTheImagesOfFreshOnesOrSaysWhyNot) {
  const auto [small, smallAovs] = renderWithGuides(96);
  const Image large = renderCornellBox(3, 4);
  try {
    OptixImageDenoiser kept({true, true});
    const Image first = kept.denoise(small, {&smallAovs.albedo, &smallAovs.normal});
    EXPECT_THROW(kept.denoise(large), std::invalid_argument) << "made with guides, given none";
    const Image again = kept.denoise(small, {&smallAovs.albedo, &smallAovs.normal});
    test::expectSameImage(again, first);
    test::expectSameImage(denoiseWithOptix(small, {&smallAovs.albedo, &smallAovs.normal}), first);
    OptixImageDenoiser colourOnly({});
    const Image largeKept = colourOnly.denoise(large);
    EXPECT_EQ(colourOnly.denoise(small).width, small.width) << "resized for another image";
    test::expectSameImage(colourOnly.denoise(large), largeKept);
    test::expectSameImage(denoiseWithOptix(large), largeKept);
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("OptiX error 7990"), std::string::npos) << e.what();
    GTEST_SKIP() << "no denoiser weights in this driver: " << e.what();
  }
}

TEST(GpuDenoiser, RejectsGuidesOfAnotherSize) {
  Image beauty(8, 8), albedo(4, 4);
  EXPECT_THROW(denoiseWithOptix(beauty, {&albedo, nullptr}), std::invalid_argument);
}

}  // namespace
}  // namespace candela
