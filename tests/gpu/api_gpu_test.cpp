// The public C++ interface (include/candela) rendering on the OptiX backend, as a program or the Python module
// asks for it: backend "optix" renders on the GPU, says so, and gives the CPU backend's picture.
#include <gtest/gtest.h>

#include <cmath>

#include "candela/candela.h"

namespace api = candela::api;

namespace {

api::RenderOptions cornellOptions(const char* backend) {
  api::RenderOptions options;
  options.width = 64;
  options.height = 48;
  options.samplesPerPixel = 256;
  options.backend = backend;
  return options;
}

double mean(const api::Image& image) {
  double sum = 0.0;
  for (size_t i = 0; i < image.size(); ++i) sum += image.data()[i];
  return sum / double(image.size());
}

}  // namespace

// 64 x 48 pixels at 256 samples: each image mean has a relative standard error of about 0.3%, so 2% apart is a
// different picture, not noise.
TEST(ApiOnGpu, RendersOnTheOptixBackendAsTheCpuBackendDoes) {
  const api::Scene scene = api::Scene::load("cornell-box");
  const api::RenderResult gpu = api::render(scene, cornellOptions("optix"));
  const api::RenderResult cpu = api::render(scene, cornellOptions("cpu"));
  EXPECT_EQ(gpu.backend, "optix");
  EXPECT_EQ(cpu.backend, "cpu");
  ASSERT_EQ(gpu.image.size(), cpu.image.size());
  for (size_t i = 0; i < gpu.image.size(); ++i) ASSERT_TRUE(std::isfinite(gpu.image.data()[i]));
  EXPECT_EQ(gpu.samplesPerPixel, 256u);
  EXPECT_EQ(gpu.invalidSamples, 0u);
  EXPECT_NEAR(mean(gpu.image) / mean(cpu.image), 1.0, 0.02);
}

TEST(ApiOnGpu, ReturnsTheAovsAndTheDenoisedImage) {
  api::RenderOptions options = cornellOptions("optix");
  options.samplesPerPixel = 4;
  options.aovs = {"albedo", "normal", "depth"};
  options.denoiser = "atrous";
  const api::RenderResult result = api::render(api::Scene::load("cornell-box"), options);
  EXPECT_EQ(result.backend, "optix");
  ASSERT_EQ(result.aovs.size(), 3u);
  EXPECT_GT(mean(result.aovs.at("albedo")), 0.0);
  EXPECT_GT(mean(result.aovs.at("depth")), 0.0);
  for (size_t i = 0; i < result.image.size(); ++i) ASSERT_TRUE(std::isfinite(result.image.data()[i]));
  EXPECT_GT(mean(result.image), 0.01);
}
