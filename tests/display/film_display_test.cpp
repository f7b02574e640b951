// The CPU backend's display frames (Backend::display, backends/film_display.h): each source gives the frame of the
// image that readImage or the filter gives, and frames stay valid as promised.
#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "backends/cpu/cpu_backend.h"
#include "backends/film_display.h"
#include "image/filters/bilateral.h"
#include "scene/builtin_scenes.h"

namespace candela {
namespace {

class CpuFilmDisplay : public testing::Test {
 protected:
  void SetUp() override {
    const Scene scene = makeCornellBox();
    RenderSettings settings;
    settings.width = 64;
    settings.height = 46;
    settings.seed = 3;
    backend_.setScene(scene);
    backend_.setSettings(settings);
    backend_.setAovsEnabled(true);
    camera_ = scene.camera.toCamera(float(settings.width) / float(settings.height));
    backend_.setCamera(camera_);
    backend_.render(4);
  }

  std::vector<uint8_t> bytes(const DisplayRequest& request) const {
    const DisplayFrame frame = backend_.display().read(request);
    return {frame.rgb, frame.rgb + size_t(frame.width) * frame.height * 3};
  }

  static std::vector<uint8_t> bytesOf(const Image& image, const DisplaySettings& display, uint32_t divisor = 1) {
    const DisplaySize size = displaySize(image.width, image.height, divisor);
    std::vector<uint8_t> out(size_t(size.width) * size.height * 3);
    writeDisplayPixels({image.pixels.data(), nullptr, image.width, image.height}, display, divisor, out.data());
    return out;
  }

  CpuBackend backend_;
  Camera camera_;
};

TEST_F(CpuFilmDisplay, OfTheAccumulatedImage) {
  for (uint32_t divisor : {1u, 2u, 5u}) {
    DisplayRequest request;
    request.display = {0.7f, ToneMapper::Reinhard};
    request.divisor = divisor;
    const DisplayFrame frame = backend_.display().read(request);
    EXPECT_EQ(frame.width, 64u / divisor);
    EXPECT_EQ(frame.height, 46u / divisor);
    EXPECT_EQ(frame.filterMilliseconds, 0.0);
    EXPECT_GE(frame.milliseconds, 0.0);
    EXPECT_EQ(bytes(request), bytesOf(backend_.readImage(), request.display, divisor)) << "divisor " << divisor;
  }
}

TEST_F(CpuFilmDisplay, ThroughTheFilters) {
  DisplayRequest request;
  AtrousParams atrous;
  atrous.passes = 3;
  request.source = AtrousFiltered{atrous};
  EXPECT_EQ(bytes(request), bytesOf(backend_.filters().atrous(atrous), request.display));
  const DisplayFrame frame = backend_.display().read(request);
  EXPECT_GT(frame.filterMilliseconds, 0.0);
  EXPECT_GE(frame.milliseconds, frame.filterMilliseconds);

  request.source = BilateralFiltered{BilateralParams{}};
  EXPECT_EQ(bytes(request), bytesOf(backend_.filters().bilateral(BilateralParams{}), request.display));

  // Two temporal filters fed alike keep alike histories.
  const std::unique_ptr<TemporalDenoiser> shown = backend_.filters().temporal(TemporalParams{});
  const std::unique_ptr<TemporalDenoiser> read = backend_.filters().temporal(TemporalParams{});
  for (bool continues : {false, true}) {
    request.source = TemporalFiltered{shown.get(), camera_, continues};
    EXPECT_EQ(bytes(request), bytesOf(read->denoise(camera_, continues), request.display));
    backend_.render(1);
  }
}

// The smoothing pass keeps the emission the camera sees (the Cornell box's light) out of the filter, as the
// viewer's display pass does, where the film records it; without the AOVs it filters the whole image.
TEST_F(CpuFilmDisplay, WithTheSmoothingPass) {
  DisplayRequest request;
  request.smoothing = BilateralParams{};
  request.divisor = 2;
  const Image emission = backend_.readEmission();
  EXPECT_EQ(bytes(request),
            bytesOf(bilateralFilter(backend_.readImage(), emission, BilateralParams{}), request.display, 2));
  EXPECT_NE(bytes(request), bytesOf(bilateralFilter(backend_.readImage(), BilateralParams{}), request.display, 2));
  request.source = AtrousFiltered{AtrousParams{}};
  EXPECT_EQ(bytes(request),
            bytesOf(bilateralFilter(backend_.filters().atrous(AtrousParams{}), emission, BilateralParams{}),
                    request.display, 2));
  backend_.setAovsEnabled(false);
  backend_.render(2);
  request.source = AccumulatedImage{};
  EXPECT_EQ(bytes(request), bytesOf(bilateralFilter(backend_.readImage(), BilateralParams{}), request.display, 2));
}

// A frame's pixels outlive the next read, so that one frame can be encoded while the next is made.
TEST_F(CpuFilmDisplay, FramesLastUntilTheSecondReadAfter) {
  DisplayRequest request;
  const DisplayFrame first = backend_.display().read(request);
  const std::vector<uint8_t> firstBytes(first.rgb, first.rgb + size_t(first.width) * first.height * 3);
  request.display.exposure = 2.0f;
  const DisplayFrame second = backend_.display().read(request);
  EXPECT_NE(second.rgb, first.rgb);
  EXPECT_EQ(std::vector<uint8_t>(first.rgb, first.rgb + firstBytes.size()), firstBytes);
}

TEST_F(CpuFilmDisplay, RefusesWhatItCannotShow) {
  DisplayRequest request;
  request.divisor = 47;
  EXPECT_THROW(backend_.display().read(request), std::invalid_argument);
  request.divisor = 1;
  request.source = TemporalFiltered{};
  EXPECT_THROW(backend_.display().read(request), std::invalid_argument);
  backend_.setAovsEnabled(false);
  request.source = AtrousFiltered{};
  EXPECT_THROW(backend_.display().read(request), std::logic_error);
}

}  // namespace
}  // namespace candela
