// The OptiX backend's display frames (Backend::display), made on the device, against the CPU's display frames
// (image/display_pixels.h) of the same linear images: the film's means, and the CUDA filters' outputs read back.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include "backends/film_display.h"
#include "gpu_render.h"
#include "image/filters/bilateral.h"

namespace candela {
namespace {

std::vector<uint8_t> bytesOf(const DisplayFrame& frame) {
  return {frame.rgb, frame.rgb + size_t(frame.width) * frame.height * 3};
}

std::vector<uint8_t> cpuBytes(const Image& image, const DisplaySettings& display, uint32_t divisor) {
  const DisplaySize size = displaySize(image.width, image.height, divisor);
  std::vector<uint8_t> bytes(size_t(size.width) * size.height * 3);
  writeDisplayPixels({image.pixels.data(), nullptr, image.width, image.height}, display, divisor, bytes.data());
  return bytes;
}

// Both sides compute each byte with the same float operations in the same order (image/display_kernel.h: no fused
// multiply-adds, IEEE division, the exposure's factor from the host, the same sRGB byte table instead of powf),
// so the bytes are equal (so they were on an H200). Prints how many channels differ, and by how much, where any do.
void expectSameBytes(const std::vector<uint8_t>& gpu, const std::vector<uint8_t>& cpu, const std::string& what) {
  ASSERT_EQ(gpu.size(), cpu.size()) << what;
  int worst = 0;
  size_t differing = 0;
  for (size_t i = 0; i < gpu.size(); ++i) {
    const int d = std::abs(int(gpu[i]) - int(cpu[i]));
    worst = std::max(worst, d);
    differing += d != 0;
  }
  if (differing)
    std::printf("%s: %zu of %zu channels differ, by at most %d\n", what.c_str(), differing, gpu.size(), worst);
  EXPECT_EQ(differing, 0u) << what;
}

class OptixDisplay : public testing::Test {
 protected:
  void SetUp() override {
    const Scene scene = makeCornellBox();
    RenderSettings settings;
    settings.width = 161;  // no divisor below divides it
    settings.height = 94;
    settings.seed = 7;
    gpu_ = test::makeBackend<OptixBackend>(scene, settings);
    gpu_->setAovsEnabled(true);
    camera_ = scene.camera.toCamera(float(settings.width) / float(settings.height));
    gpu_->setCamera(camera_);
    gpu_->render(4);
  }

  std::unique_ptr<OptixBackend> gpu_;
  Camera camera_;
};

TEST_F(OptixDisplay, OfTheFilmAreTheCpuFramesOfItsImage) {
  const Image image = gpu_->readImage();
  for (ToneMapper mapper : {ToneMapper::AcesFilmic, ToneMapper::Clamp, ToneMapper::Reinhard})
    for (float exposure : {0.0f, 1.7f, -2.5f})
      for (uint32_t divisor : {1u, 2u, 3u, 4u}) {
        DisplayRequest request;
        request.display = {exposure, mapper};
        request.divisor = divisor;
        const DisplayFrame frame = gpu_->display().read(request);
        EXPECT_EQ(frame.width, 161u / divisor);
        EXPECT_EQ(frame.height, 94u / divisor);
        EXPECT_EQ(frame.filterMilliseconds, 0.0);
        expectSameBytes(bytesOf(frame), cpuBytes(image, request.display, divisor),
                        std::string(toneMapperName(mapper)) + ", exposure " + std::to_string(exposure) + ", divisor " +
                            std::to_string(divisor));
      }
}

TEST_F(OptixDisplay, ThroughTheCudaFiltersAreTheCpuFramesOfTheirOutput) {
  DisplayRequest request;
  request.divisor = 2;
  AtrousParams atrous;
  atrous.passes = 4;
  request.source = AtrousFiltered{atrous};
  const DisplayFrame frame = gpu_->display().read(request);
  EXPECT_GT(frame.filterMilliseconds, 0.0);
  EXPECT_GE(frame.milliseconds, frame.filterMilliseconds);
  expectSameBytes(bytesOf(frame), cpuBytes(gpu_->filters().atrous(atrous), request.display, 2), "a-trous");

  request.source = BilateralFiltered{BilateralParams{}};
  expectSameBytes(bytesOf(gpu_->display().read(request)),
                  cpuBytes(gpu_->filters().bilateral(BilateralParams{}), request.display, 2), "bilateral");

  // Two temporal filters of the backend fed alike keep alike histories.
  const std::unique_ptr<TemporalDenoiser> shown = gpu_->filters().temporal(TemporalParams{});
  const std::unique_ptr<TemporalDenoiser> read = gpu_->filters().temporal(TemporalParams{});
  for (bool continues : {false, true}) {
    request.source = TemporalFiltered{shown.get(), camera_, continues};
    expectSameBytes(bytesOf(gpu_->display().read(request)),
                    cpuBytes(read->denoise(camera_, continues), request.display, 2), "temporal");
    gpu_->render(1);
  }
}

// The smoothing pass is the CUDA bilateral filter, which gives the CPU filter's image (filters_gpu_test.cpp), with
// the film's emission kept apart.
TEST_F(OptixDisplay, WithTheSmoothingPassAreTheCpuFramesOfTheSmoothedImage) {
  DisplayRequest request;
  request.smoothing = BilateralParams{};
  const Image emission = gpu_->readEmission();
  expectSameBytes(bytesOf(gpu_->display().read(request)),
                  cpuBytes(bilateralFilter(gpu_->readImage(), emission, BilateralParams{}), request.display, 1),
                  "smoothed film");
  request.source = AtrousFiltered{AtrousParams{}};
  expectSameBytes(bytesOf(gpu_->display().read(request)),
                  cpuBytes(bilateralFilter(gpu_->filters().atrous(AtrousParams{}), emission, BilateralParams{}),
                           request.display, 1),
                  "smoothed a-trous");
}

TEST_F(OptixDisplay, FramesLastUntilTheSecondReadAfter) {
  DisplayRequest request;
  const DisplayFrame first = gpu_->display().read(request);
  const std::vector<uint8_t> firstBytes = bytesOf(first);
  request.display.exposure = 2.0f;
  const DisplayFrame second = gpu_->display().read(request);
  EXPECT_NE(second.rgb, first.rgb);
  EXPECT_EQ(bytesOf(first), firstBytes);
}

TEST_F(OptixDisplay, RefusesWhatItCannotShow) {
  DisplayRequest request;
  request.divisor = 95;
  EXPECT_THROW(gpu_->display().read(request), std::invalid_argument);
  request.divisor = 1;
  CpuBackend cpu;
  const std::unique_ptr<TemporalDenoiser> foreign = cpu.filters().temporal(TemporalParams{});
  request.source = TemporalFiltered{foreign.get(), camera_, false};
  EXPECT_THROW(gpu_->display().read(request), std::invalid_argument);
  gpu_->setAovsEnabled(false);
  request.source = AtrousFiltered{};
  EXPECT_THROW(gpu_->display().read(request), std::logic_error);
}

}  // namespace
}  // namespace candela
