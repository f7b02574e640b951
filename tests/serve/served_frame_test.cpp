// What candela serve sends of a frame: InteractiveRenderer::step with serve's present (FrameImages::display, the
// backend's display frame of the post settings' image).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "app/interactive/interactive_renderer.h"
#include "app/serve/frame_encoding.h"

namespace candela {
namespace {

namespace fs = std::filesystem;

// A front end that presents as candela serve does, and keeps the frame's images before the filter.
struct ServeLikeFrontEnd final : FrontEnd {
  DisplayImage shown;
  DisplayImage onTheHost;  // the same frame through the post settings on the host (FrameImages::filtered)
  Image image, emission;

  FlyKeys takeInput() override { return {}; }
  void present(FrameImages& frame) override {
    const DisplayFrame pixels = frame.display();
    shown = {pixels.width, pixels.height,
             std::vector<uint8_t>(pixels.rgb, pixels.rgb + size_t(pixels.width) * pixels.height * 3)};
    onTheHost = displayImage(frame.filtered(), frame.post().display);
    image = frame.image();
    emission = frame.emission() ? *frame.emission() : Image();
  }
  void report(const std::string& message, bool) override { ADD_FAILURE() << message; }
};

// A bright emitter in the dark: an emissive square of black base colour filling the middle of the view, with
// nothing else in the scene to light.
std::string writeEmitterScene(const fs::path& folder) {
  fs::create_directories(folder);
  std::ofstream(folder / "emitter.mtl") << "newmtl light\nKd 0 0 0\nKe 1 1 1\n";
  std::ofstream(folder / "emitter.obj") << "mtllib emitter.mtl\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
                                           "usemtl light\nf 1 2 3 4\n";
  std::ofstream(folder / "scene.json") << R"({"models": [{"file": "emitter.obj"}],
      "environment": {"radiance": [0, 0, 0]}, "camera": {"position": [0, 0, 4], "target": [0, 0, 0]}})";
  return (folder / "scene.json").string();
}

class ServedFrame : public testing::TestWithParam<DenoiserChoice> {};

// With the a-trous denoiser the bilateral pass is the display frame's smoothing pass, without it the film filter.
TEST_P(ServedFrame, TheBilateralFilterLeavesEmittersAsTheyAre) {
  const fs::path folder = fs::temp_directory_path() / ("candela-served-frame-" + std::to_string(::getpid()));
  InteractiveOptions options;
  options.sceneSpec = writeEmitterScene(folder);
  options.backend = "cpu";
  options.post.denoiser = GetParam();
  options.post.bilateral = true;
  options.post.bilateralParams = {4, 3.0f, 100.0f};  // a wide range: nearly a Gaussian blur
  options.post.display = {-1.0f, ToneMapper::Clamp};
  InteractiveRenderer renderer(options);
  ServeLikeFrontEnd frontEnd;
  for (int frame = 0; frame < 4; ++frame) renderer.step({32, 32, frame / 30.0, 1 / 30.0}, frontEnd);
  fs::remove_all(folder);

  ASSERT_EQ(frontEnd.emission.pixels.size(), frontEnd.image.pixels.size());
  const DisplayImage unfiltered = displayImage(frontEnd.image, options.post.display);
  // What serve sent before: the filter over the whole image, which blurs the emitter's edge into the dark.
  const DisplayImage wholeImage =
      displayImage(bilateralFilter(frontEnd.image, options.post.bilateralParams), options.post.display);
  ASSERT_EQ(frontEnd.shown.rgb.size(), unfiltered.rgb.size());
  EXPECT_EQ(frontEnd.shown.rgb, frontEnd.onTheHost.rgb) << "the display frame is the host's post image";
  size_t emitterPixels = 0, keptAsTheyAre = 0, blurredByTheWholeImageFilter = 0;
  for (size_t i = 0; i < frontEnd.emission.pixels.size(); ++i) {
    if (!(frontEnd.emission.pixels[i].x > 0.0f)) continue;
    ++emitterPixels;
    bool kept = true;
    for (size_t c = 0; c < 3; ++c) kept = kept && frontEnd.shown.rgb[3 * i + c] == unfiltered.rgb[3 * i + c];
    keptAsTheyAre += kept;
    if (wholeImage.rgb[3 * i] != unfiltered.rgb[3 * i]) ++blurredByTheWholeImageFilter;
  }
  EXPECT_GT(emitterPixels, 200u);
  EXPECT_GT(blurredByTheWholeImageFilter, 20u) << "the test sees an emitter smoothed";
  // Without a denoiser every emitter pixel is the film's. The a-trous filter smooths the emission on its own, so
  // along the emitter's edge its image differs from the recorded emission that the bilateral pass keeps apart, and
  // there the pass may move a pixel; far fewer than the whole-image filter moves.
  if (GetParam() == DenoiserChoice::None)
    EXPECT_EQ(keptAsTheyAre, emitterPixels);
  else
    EXPECT_LT(emitterPixels - keptAsTheyAre, blurredByTheWholeImageFilter / 2)
        << emitterPixels << " emitter pixels, " << keptAsTheyAre << " kept, " << blurredByTheWholeImageFilter
        << " moved by the whole-image filter";
}

INSTANTIATE_TEST_SUITE_P(Denoisers, ServedFrame, testing::Values(DenoiserChoice::None, DenoiserChoice::Atrous),
                         [](const testing::TestParamInfo<DenoiserChoice>& choice) {
                           return std::string(denoiserName(choice.param));
                         });

}  // namespace
}  // namespace candela
