// The frame step that candela view and candela serve share, on the CPU backend.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/interactive/interactive_renderer.h"
#include "app/interactive/post_filter.h"
#include "support/animated_gltf.h"

namespace candela {
namespace {

// Records the frame step's calls to it, and what it was given to present.
struct RecordingFrontEnd final : FrontEnd {
  std::vector<std::string> calls;
  std::function<void()> onInput;  // feeds the renderer's CameraInput, as a window or page would
  bool neededHost = false;
  bool hadEmission = false;
  Image image, emission, filtered;
  std::vector<std::string> reports;

  FlyKeys takeInput() override {
    calls.push_back("input");
    if (onInput) onInput();
    return {};
  }
  void adjustPlan(FramePlan&) override { calls.push_back("plan"); }
  void present(FrameImages& frame) override {
    calls.push_back("present");
    neededHost = frame.needsHost();
    hadEmission = frame.emission() != nullptr;
    image = frame.image();
    if (hadEmission) emission = *frame.emission();
    filtered = frame.filtered();
  }
  void report(const std::string& message, bool) override { reports.push_back(message); }
};

InteractiveOptions cpuOptions(const std::string& scene) {
  InteractiveOptions options;
  options.sceneSpec = scene;
  options.backend = "cpu";
  return options;
}

constexpr uint32_t kWidth = 40, kHeight = 30;

// Frame `i` of a front end showing 30 frames a second.
FrameRequest frameAt(int i) { return {kWidth, kHeight, i / 30.0, 1 / 30.0}; }

TEST(InteractiveRenderer, AFrameTakesInputPlansRendersAndPresents) {
  InteractiveRenderer renderer(cpuOptions("cornell-box"));
  RecordingFrontEnd frontEnd;
  for (int i = 0; i < 3; ++i) {
    const FrameOutcome outcome = renderer.step(frameAt(i), frontEnd);
    EXPECT_EQ(outcome.plan.width, kWidth);
    EXPECT_EQ(outcome.plan.height, kHeight);
    EXPECT_FALSE(outcome.plan.preview) << "a scene's first camera is where the view starts, not a motion";
    EXPECT_GT(outcome.seconds, 0.0);
  }
  EXPECT_EQ(frontEnd.calls, (std::vector<std::string>{"input", "plan", "present", "input", "plan", "present", "input",
                                                      "plan", "present"}));
  EXPECT_EQ(renderer.session().accumulatedSamples(), 3u);
  EXPECT_FALSE(frontEnd.neededHost) << "without a denoiser or the filter the image may stay on the device";
  EXPECT_FALSE(frontEnd.hadEmission);
  EXPECT_EQ(frontEnd.image.width, kWidth);
  EXPECT_EQ(frontEnd.filtered.pixels.size(), frontEnd.image.pixels.size());
}

TEST(InteractiveRenderer, InputThatMovesTheCameraMakesAPreviewAndStartsOver) {
  InteractiveRenderer renderer(cpuOptions("cornell-box"));
  RecordingFrontEnd frontEnd;
  for (int i = 0; i < 3; ++i) renderer.step(frameAt(i), frontEnd);
  const uint64_t restarts = renderer.session().restarts();
  frontEnd.onInput = [&] { renderer.input().wheel(1.0, /*overImage=*/true); };
  const FrameOutcome moved = renderer.step(frameAt(3), frontEnd);
  EXPECT_TRUE(moved.plan.preview);
  EXPECT_EQ(moved.plan.samplesPerPixel, 1u);
  EXPECT_EQ(renderer.session().restarts(), restarts + 1);
  EXPECT_EQ(renderer.session().accumulatedSamples(), 1u);
}

// The viewer's way for both front ends: the bilateral filter makes the backend record the emission, and keeps it
// out of its sums, with or without a denoiser.
TEST(InteractiveRenderer, TheBilateralFilterKeepsTheEmissionApart) {
  InteractiveOptions options = cpuOptions("cornell-box");
  options.post.bilateral = true;
  InteractiveRenderer renderer(options);
  RecordingFrontEnd frontEnd;
  for (int i = 0; i < 2; ++i) renderer.step(frameAt(i), frontEnd);
  EXPECT_TRUE(renderer.session().backend().aovsEnabled());
  EXPECT_TRUE(frontEnd.neededHost);
  ASSERT_TRUE(frontEnd.hadEmission);
  ASSERT_EQ(frontEnd.emission.pixels.size(), frontEnd.image.pixels.size());
  const Image expected = bilateralFilter(frontEnd.image, frontEnd.emission, options.post.bilateralParams);
  for (size_t i = 0; i < expected.pixels.size(); ++i) {
    EXPECT_EQ(frontEnd.filtered.pixels[i].x, expected.pixels[i].x) << i;
    EXPECT_EQ(frontEnd.filtered.pixels[i].z, expected.pixels[i].z) << i;
  }
  const Image post = renderer.postImage();
  EXPECT_EQ(post.pixels[0].y, expected.pixels[0].y);
}

TEST(InteractiveRenderer, AnOptixDenoiserThisBuildLacksIsReportedAndTurnedOff) {
  if (inThisBuild(DenoiserChoice::Optix)) GTEST_SKIP() << "this build has the OptiX AI denoiser";
  InteractiveOptions options = cpuOptions("cornell-box");
  options.post.denoiser = DenoiserChoice::Optix;
  InteractiveRenderer renderer(options);
  RecordingFrontEnd frontEnd;
  renderer.step(frameAt(0), frontEnd);
  ASSERT_EQ(frontEnd.reports.size(), 1u);
  EXPECT_NE(frontEnd.reports[0].find("no OptiX AI denoiser"), std::string::npos) << frontEnd.reports[0];
  EXPECT_EQ(renderer.controls().post.denoiser, DenoiserChoice::None);
}

struct AnimatedScene : ::testing::Test {
  std::filesystem::path folder =
      std::filesystem::temp_directory_path() / ("candela-interactive-" + std::to_string(::getpid()) + "-" +
                                                ::testing::UnitTest::GetInstance()->current_test_info()->name());
  std::string file;
  void SetUp() override {
    std::filesystem::create_directories(folder);
    file = test::AnimatedFile().write(folder);
  }
  void TearDown() override { std::filesystem::remove_all(folder); }
};

TEST_F(AnimatedScene, PlaysWithTheClockAndStandsWhenPaused) {
  InteractiveRenderer renderer(cpuOptions(file));
  RecordingFrontEnd frontEnd;
  EXPECT_EQ(renderer.controls().animation.clip, 0);
  EXPECT_TRUE(renderer.controls().animation.playing);
  renderer.step({kWidth, kHeight, 0.0, 0.25}, frontEnd);
  EXPECT_FLOAT_EQ(renderer.controls().animation.time, 0.25f);
  // Each new pose is a motion: a preview, and the accumulation starts over.
  const FrameOutcome playing = renderer.step({kWidth, kHeight, 0.25, 0.25}, frontEnd);
  EXPECT_FLOAT_EQ(renderer.controls().animation.time, 0.5f);
  EXPECT_TRUE(playing.plan.preview);
  EXPECT_EQ(renderer.session().accumulatedSamples(), 1u);
  renderer.controls().animation.playing = false;
  renderer.step({kWidth, kHeight, 5.0, 0.25}, frontEnd);
  const uint32_t samples = renderer.session().accumulatedSamples();
  const FrameOutcome paused = renderer.step({kWidth, kHeight, 5.25, 0.25}, frontEnd);
  EXPECT_FLOAT_EQ(renderer.controls().animation.time, 0.5f);
  EXPECT_FALSE(paused.plan.preview);
  EXPECT_EQ(renderer.session().accumulatedSamples(), samples + 1);
}

TEST_F(AnimatedScene, TheAnimationOptionChoosesTheClip) {
  InteractiveOptions options = cpuOptions(file);
  options.animation = "Bounce";
  EXPECT_EQ(InteractiveRenderer(options).controls().animation.clip, 1);
  options.animation = "1";
  EXPECT_EQ(InteractiveRenderer(options).controls().animation.clip, 1);
  options.animation = "Walk";
  EXPECT_THROW(InteractiveRenderer{options}, std::runtime_error);
}

TEST(InteractiveRenderer, TheAnimationOptionNeedsAnAnimation) {
  InteractiveOptions options = cpuOptions("cornell-box");
  options.animation = "0";
  try {
    InteractiveRenderer renderer(options);
    FAIL() << "cornell-box has no animation to play";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no animation '0'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace candela
