// `candela view` as a user runs it, on an X display (CTest starts Xvfb): headless frames and screenshots, mouse
// and keyboard through xdotool, load errors, and the absence of a display.
#include <gtest/gtest.h>
#include <stb/stb_image.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <thread>

#include "app/interactive/orbit_camera.h"
#include "app/interactive/scene_summary.h"
#include "child_process.h"
#include "image_agreement.h"
#include "scene/builtin_scenes.h"

namespace candela {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::ChildProcess;
using test::runCommand;

const std::string kCandela = CANDELA_EXECUTABLE;
constexpr double kProcessTimeout = 60.0;
// The viewer takes at most one key press per frame from its input queue, and writes the state after every event
// sent before the F12 that asks for it; at a few frames per second on a loaded machine that can take seconds.
constexpr double kStateTimeout = 30.0;

struct Png {
  int width = 0, height = 0;
  std::vector<double> rgb;

  // The rectangle (x, y, w, h) of this image, as another Png.
  Png crop(int x, int y, int w, int h) const {
    Png out{w, h, {}};
    for (int r = y; r < y + h; ++r)
      for (int c = x; c < x + w; ++c)
        for (int k = 0; k < 3; ++k) out.rgb.push_back(rgb[(size_t(r) * width + c) * 3 + k]);
    return out;
  }
  Png upsideDown() const {
    Png out = *this;
    for (int r = 0; r < height; ++r)
      std::copy_n(rgb.begin() + ptrdiff_t(height - 1 - r) * width * 3, width * 3,
                  out.rgb.begin() + ptrdiff_t(r) * width * 3);
    return out;
  }
};

Png readPng(const fs::path& path) {
  Png png;
  int channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &png.width, &png.height, &channels, 3);
  if (!data) throw std::runtime_error("cannot read " + path.string());
  png.rgb.assign(data, data + size_t(png.width) * png.height * 3);
  stbi_image_free(data);
  return png;
}

class ViewerWindow : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_NE(std::getenv("DISPLAY"), nullptr) << "these tests need an X display; CTest runs them under Xvfb";
    dir_ = fs::temp_directory_path() / ("candela-viewer-" + std::to_string(::getpid()) + "-" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  fs::path dir_;
};

TEST_F(ViewerWindow, FramesThenScreenshotMatchAHeadlessRender) {
  const std::string size[] = {"--width", "96", "--height", "72"};
  std::string log;
  ASSERT_EQ(runCommand({kCandela, "view", "cornell-box", size[0], size[1], size[2], size[3], "--frames", "16", "--seed",
                        "1", "--screenshot", path("view.png"), "--window-capture", path("window.png")},
                       kProcessTimeout, &log),
            0)
      << log;
  auto render = [&](const std::string& out, const std::string& seed, const std::string& depth) {
    std::string renderLog;
    ASSERT_EQ(runCommand({kCandela, "render", "cornell-box", size[0], size[1], size[2], size[3], "--spp", "16",
                          "--seed", seed, "--max-depth", depth, "-o", path(out)},
                         kProcessTimeout, &renderLog),
              0)
        << renderLog;
  };
  render("render.png", "2", "8");
  render("direct-only.png", "3", "1");

  const Png view = readPng(path("view.png")), reference = readPng(path("render.png"));
  ASSERT_EQ(view.width, 96);
  ASSERT_EQ(view.height, 72);
  auto agreement = [&](const Png& other) {
    return test::compareIndependentRenders(view.rgb, other.rgb, view.width, view.height, 3, 8, 0.01);
  };
  test::AgreementReport same = agreement(reference);
  EXPECT_TRUE(same.agree) << "statistic " << same.worstStatistic << " at " << same.worstBlock << " over "
                          << same.threshold;
  // The comparison has the power to see what would go wrong: light missing, or the picture upside down.
  EXPECT_FALSE(agreement(readPng(path("direct-only.png"))).agree);
  EXPECT_FALSE(agreement(reference.upsideDown()).agree);

  // What the window showed is the screenshot: the GLSL tone mapping agrees with the PNG writer's to a step.
  const Png window = readPng(path("window.png"));
  ASSERT_GE(window.width, 96);
  ASSERT_EQ(window.height, 72);
  const Png shown = window.crop(0, 0, 96, 72);
  double worst = 0.0;
  for (size_t i = 0; i < shown.rgb.size(); ++i) worst = std::max(worst, std::fabs(shown.rgb[i] - view.rgb[i]));
  EXPECT_LE(worst, 1.0);
}

// Drives a running viewer with xdotool and reads the state it writes on F12: the state after every mouse and key
// event sent before.
class RunningViewer {
 public:
  RunningViewer(const fs::path& dir, std::vector<std::string> extraArgs)
      : statePath_((dir / "state.json").string()), child_(arguments(extraArgs), (dir / "stderr.txt").string()) {
    const std::string idPath = (dir / "window-id").string();
    const std::string search = "timeout 20 xdotool search --sync --onlyvisible --name '^candela - ' > '" + idPath + "'";
    if (std::system(search.c_str()) != 0 || !(std::ifstream(idPath) >> window_))
      throw std::runtime_error("the viewer's window did not appear: " + child_.stderrText());
  }

  // Runs `xdotool <arguments>` through the shell; throws when it fails.
  static void xdotool(const std::string& arguments) {
    if (std::system(("xdotool " + arguments).c_str()) != 0)
      throw std::runtime_error("xdotool " + arguments + " failed");
  }
  // Moves the pointer to (x, y) in the window.
  void pointAt(double x, double y) const {
    xdotool("mousemove --window " + window_ + " " + std::to_string(int(x)) + " " + std::to_string(int(y)));
  }
  void drag(int button, double x, double y, int dx, int dy) const {
    pointAt(x, y);
    xdotool("mousedown " + std::to_string(button));
    for (int step = 1; step <= 4; ++step) {
      xdotool("mousemove_relative -- " + std::to_string(dx / 4) + " " + std::to_string(dy / 4));
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    xdotool("mouseup " + std::to_string(button));
  }

  json state() {
    fs::remove(statePath_);
    xdotool("key F12");
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(kStateTimeout);
    while (std::chrono::steady_clock::now() < deadline) {
      if (fs::exists(statePath_)) return json::parse(std::ifstream(statePath_));
      if (!child_.running()) throw std::runtime_error("the viewer exited: " + child_.stderrText());
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    throw std::runtime_error("the viewer wrote no state within " + std::to_string(int(kStateTimeout)) + " s");
  }
  // Asks for the state until `done` holds, for at most `seconds`.
  json stateWhen(const std::function<bool(const json&)>& done, double seconds = 10.0) {
    auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    json s = state();
    while (!done(s)) {
      if (std::chrono::steady_clock::now() > deadline) throw std::runtime_error("timed out; last state " + s.dump());
      std::this_thread::sleep_for(std::chrono::milliseconds(30));
      s = state();
    }
    return s;
  }

  ChildProcess& process() { return child_; }

 private:
  std::vector<std::string> arguments(std::vector<std::string> extra) const {
    std::vector<std::string> argv = {kCandela, "view", "--state-file", statePath_};
    argv.insert(argv.end(), extra.begin(), extra.end());
    return argv;
  }

  std::string statePath_;
  ChildProcess child_;
  std::string window_;
};

Vec3 vec(const json& j) { return {j[0].get<float>(), j[1].get<float>(), j[2].get<float>()}; }
float distance(Vec3 a, Vec3 b) { return length(a - b); }
constexpr float kSame = 1e-5f;

TEST_F(ViewerWindow, MouseAndKeysMoveTheCameraAndRestartAccumulation) {
  constexpr int kWidth = 160, kHeight = 120;
  RunningViewer viewer(dir_, {"cornell-box", "--width", std::to_string(kWidth), "--height", std::to_string(kHeight)});
  viewer.pointAt(kWidth / 2, kHeight / 2);
  json s = viewer.stateWhen([](const json& j) { return j["accumulated_samples"] >= 2; });
  EXPECT_EQ(s["image_width"], kWidth);
  const Vec3 home = vec(s["camera"]["position"]);

  // A drag that starts over the panel leaves the camera alone.
  viewer.drag(3, kWidth + 150, 40, 60, 20);
  json t = viewer.state();
  EXPECT_LT(distance(vec(t["camera"]["position"]), home), kSame);
  EXPECT_EQ(t["restarts"], s["restarts"]);

  // Right-drag orbits: the eye moves around a fixed target at a fixed distance, and accumulation starts over.
  viewer.drag(3, kWidth / 2, kHeight / 2, 80, 20);
  s = t;
  t = viewer.state();
  EXPECT_GT(distance(vec(t["camera"]["position"]), vec(s["camera"]["position"])), 0.05f);
  EXPECT_LT(distance(vec(t["camera"]["target"]), vec(s["camera"]["target"])), kSame);
  EXPECT_NEAR(t["camera"]["distance"].get<float>(), s["camera"]["distance"].get<float>(), kSame);
  EXPECT_GT(t["restarts"], s["restarts"]);

  // Once the camera rests, frames are full size again and accumulate.
  s = viewer.stateWhen([&](const json& j) { return !j["preview"] && j["accumulated_samples"] >= 3; });
  EXPECT_EQ(s["image_width"], kWidth);
  EXPECT_EQ(s["image_height"], kHeight);

  // Middle-drag pans: eye and target move together, the view direction stays.
  viewer.drag(2, kWidth / 2, kHeight / 2, 40, -20);
  t = viewer.state();
  EXPECT_GT(distance(vec(t["camera"]["target"]), vec(s["camera"]["target"])), 0.01f);
  EXPECT_LT(distance(vec(t["camera"]["forward"]), vec(s["camera"]["forward"])), kSame);
  EXPECT_NEAR(t["camera"]["distance"].get<float>(), s["camera"]["distance"].get<float>(), kSame);
  EXPECT_GT(t["restarts"], s["restarts"]);

  // The wheel dollies: two steps towards the target.
  s = t;
  viewer.pointAt(kWidth / 2, kHeight / 2);
  RunningViewer::xdotool("click --repeat 2 --delay 30 4");
  const float dollied = s["camera"]["distance"].get<float>() * OrbitCamera::kDollyStep * OrbitCamera::kDollyStep;
  t = viewer.stateWhen([&](const json& j) { return std::fabs(j["camera"]["distance"].get<float>() - dollied) < 1e-4f; },
                       5.0);
  EXPECT_LT(distance(vec(t["camera"]["forward"]), vec(s["camera"]["forward"])), kSame);
  EXPECT_GT(t["restarts"], s["restarts"]);

  // Left-drag orbits too.
  s = t;
  viewer.drag(1, kWidth / 2, kHeight / 2, -60, 0);
  t = viewer.state();
  EXPECT_GT(distance(vec(t["camera"]["position"]), vec(s["camera"]["position"])), 0.05f);
  EXPECT_LT(distance(vec(t["camera"]["target"]), vec(s["camera"]["target"])), kSame);

  // W flies forward, along the view direction.
  s = t;
  RunningViewer::xdotool("keydown w sleep 0.3 keyup w");
  t = viewer.state();
  const Vec3 step = vec(t["camera"]["target"]) - vec(s["camera"]["target"]);
  const Vec3 forward = vec(s["camera"]["forward"]);
  EXPECT_GT(dot(step, forward), 0.01f);
  EXPECT_LT(length(step - forward * dot(step, forward)), 1e-4f);
  EXPECT_GT(t["restarts"], s["restarts"]);

  // R goes home; F frames the scene's bounds.
  RunningViewer::xdotool("key r");
  t = viewer.state();
  EXPECT_LT(distance(vec(t["camera"]["position"]), home), 1e-4f);
  RunningViewer::xdotool("key f");
  t = viewer.state();
  EXPECT_LT(distance(vec(t["camera"]["target"]), summarizeScene(makeCornellBox()).bounds.centre()), 1e-4f);

  RunningViewer::xdotool("key Escape");
  EXPECT_EQ(viewer.process().wait(10.0), 0) << viewer.process().stderrText();
}

TEST_F(ViewerWindow, ALoadErrorIsShownInTheWindow) {
  RunningViewer viewer(dir_, {"cornell-box", "--width", "64", "--height", "800", "--max-depth", "1"});
  json s = viewer.state();
  const Vec3 camera = vec(s["camera"]["position"]);
  const float fieldX = s["open_scene_field"][0], fieldY = s["open_scene_field"][1];
  ASSERT_GT(fieldX, 64.0f);  // on the panel, inside the window
  ASSERT_LT(fieldY, 800.0f);

  // The pointer leaves the field straight after the click, before the viewer's next frame: the click still
  // lands on the field, and the text typed straight after it reaches the field.
  viewer.pointAt(fieldX, fieldY);
  RunningViewer::xdotool("click 1 mousemove_relative -- -200 -300");
  RunningViewer::xdotool("type --delay 20 no-such-scene");
  json t = viewer.state();
  EXPECT_TRUE(t["open_scene_field_active"]);
  EXPECT_EQ(t["open_scene_text"], "no-such-scene");
  // Typing into the field did not move the camera ('s' and 'e' are fly keys).
  EXPECT_LT(distance(vec(t["camera"]["position"]), camera), kSame);
  EXPECT_EQ(t["restarts"], s["restarts"]);
  RunningViewer::xdotool("key Return");
  t = viewer.state();
  EXPECT_FALSE(t["open_scene_field_active"]);
  EXPECT_TRUE(t["message_is_error"]);
  EXPECT_NE(t["message"].get<std::string>().find("could not open 'no-such-scene'"), std::string::npos) << t["message"];
  EXPECT_EQ(t["scene"], "cornell-box");
  EXPECT_TRUE(viewer.process().running());

  // The field keeps the failed name for correcting; Ctrl+A and Backspace clear it. Neither these keys nor the
  // new name ('a', 'w', 'e' fly, 'f' frames the scene, 'r' resets the camera) reach the camera.
  viewer.pointAt(fieldX, fieldY);
  RunningViewer::xdotool("click 1");
  t = viewer.state();
  ASSERT_TRUE(t["open_scene_field_active"]);
  EXPECT_EQ(t["open_scene_text"], "no-such-scene");
  RunningViewer::xdotool("key ctrl+a BackSpace");
  t = viewer.state();
  EXPECT_EQ(t["open_scene_text"], "");
  RunningViewer::xdotool("type --delay 20 white-furnace");
  t = viewer.state();
  EXPECT_EQ(t["open_scene_text"], "white-furnace");
  EXPECT_LT(distance(vec(t["camera"]["position"]), camera), kSame);
  EXPECT_EQ(t["restarts"], s["restarts"]);
  RunningViewer::xdotool("key Return");
  t = viewer.state();
  EXPECT_EQ(t["scene"], "white-furnace");
  EXPECT_FALSE(t["message_is_error"]);

  RunningViewer::xdotool("key Escape");
  EXPECT_EQ(viewer.process().wait(10.0), 0) << viewer.process().stderrText();
}

// The last line of `text`, without its newline.
std::string lastLine(std::string text) {
  while (!text.empty() && text.back() == '\n') text.pop_back();
  return text.substr(text.find_last_of('\n') + 1);
}

// The OptiX AI denoiser asked for at start: a build without it refuses in one sentence; a build with it denoises,
// or, where it cannot run (no GPU, or a driver without the denoiser's weights), says why in the panel and renders
// on without denoising.
TEST_F(ViewerWindow, TheOptixDenoiserRunsOrThePanelSaysWhyNot) {
#if CANDELA_HAS_OPTIX
  RunningViewer viewer(dir_,
                       {"cornell-box", "--width", "64", "--height", "64", "--max-depth", "1", "--denoise", "optix"});
  const json s = viewer.state();
  const std::string message = s["message"];
  if (s["message_is_error"]) {
    EXPECT_EQ(message.rfind("no OptiX AI denoiser: ", 0), 0u) << message;
    EXPECT_NE(message.find("; denoising is off"), std::string::npos) << message;
    EXPECT_EQ(s["denoiser"], "none");
  } else {
    EXPECT_EQ(s["denoiser"], "optix") << message;
  }
  const uint32_t samples = s["accumulated_samples"];
  viewer.stateWhen([&](const json& t) { return t["accumulated_samples"].get<uint32_t>() > samples; });
  RunningViewer::xdotool("key Escape");
  EXPECT_EQ(viewer.process().wait(10.0), 0) << viewer.process().stderrText();
#else
  std::string text;
  EXPECT_EQ(runCommand({kCandela, "view", "--denoise", "optix", "--frames", "1"}, kProcessTimeout, &text), 1);
  EXPECT_EQ(lastLine(text).rfind("candela: --denoise optix needs the OptiX backend, which is not in this build", 0), 0u)
      << text;
#endif
}

TEST_F(ViewerWindow, WithoutADisplayItSaysSoAndFails) {
  ChildProcess child({kCandela, "view", "--frames", "1"}, path("stderr.txt"), /*display=*/false);
  EXPECT_EQ(child.wait(kProcessTimeout), 1);
  const std::string text = child.stderrText();
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1) << text;
  EXPECT_NE(text.find("candela: cannot open a window: no display"), std::string::npos) << text;
}

TEST_F(ViewerWindow, AnUnknownSceneAtStartFailsWithOneSentence) {
  std::string text;
  EXPECT_EQ(runCommand({kCandela, "view", "no-such-scene", "--frames", "1"}, kProcessTimeout, &text), 1);
  EXPECT_EQ(lastLine(text).rfind("candela: unknown scene 'no-such-scene'", 0), 0u) << text;
}

}  // namespace
}  // namespace candela
