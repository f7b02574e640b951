#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <stb/stb_image.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "app/viewer/viewer_files.h"
#include "image/tonemap.h"

namespace candela {
namespace {

namespace fs = std::filesystem;

struct ViewerFiles : ::testing::Test {
  fs::path dir;
  void SetUp() override {
    dir = fs::temp_directory_path() / ("candela-viewer-files-" + std::to_string(::getpid()));
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }
};

TEST_F(ViewerFiles, ViewFileHoldsCameraAndSettings) {
  CameraDescription camera;
  camera.eye = {1, 2, 3};
  camera.target = {0, 0.5f, 0};
  camera.verticalFovDegrees = 35.0f;
  RenderSettings settings;
  settings.width = 320;
  settings.height = 200;
  settings.seed = 9;
  ViewerControls controls;
  controls.maxDepth = 5;
  controls.samplesPerFrame = 4;
  controls.environmentIntensity = 2.0f;
  controls.post.display = {1.5f, ToneMapper::Clamp};
  controls.post.bilateral = true;
  controls.post.bilateralParams = {4, 2.5f, 0.3f};
  const fs::path file = dir / "view.json";
  writeViewFile(file.string(), "cornell-box", camera, settings, controls);

  nlohmann::json j = nlohmann::json::parse(std::ifstream(file));
  EXPECT_EQ(j["scene"], "cornell-box");
  EXPECT_EQ(j["camera"]["position"], nlohmann::json::array({1.0, 2.0, 3.0}));
  EXPECT_FLOAT_EQ(j["camera"]["target"][1].get<float>(), 0.5f);
  EXPECT_FLOAT_EQ(j["camera"]["vertical_fov_degrees"].get<float>(), 35.0f);
  EXPECT_EQ(j["render"]["width"], 320);
  EXPECT_EQ(j["render"]["max_depth"], 5);
  EXPECT_EQ(j["render"]["seed"], 9);
  EXPECT_EQ(j["render"]["samples_per_frame"], 4);
  EXPECT_FLOAT_EQ(j["environment"]["intensity"].get<float>(), 2.0f);
  EXPECT_EQ(j["display"]["tone_mapper"], "clamp");
  EXPECT_EQ(j["display"]["bilateral"]["radius"], 4);
  EXPECT_THROW(writeViewFile((dir / "missing" / "view.json").string(), "x", camera, settings, controls),
               std::runtime_error);
}

TEST_F(ViewerFiles, StateFileAppearsWhole) {
  ViewerState state;
  state.frame = 12;
  state.restarts = 3;
  state.cameraPosition = {1, 2, 3};
  state.message = "could not open 'x'";
  state.messageIsError = true;
  const fs::path file = dir / "state.json";
  writeStateFile(file.string(), state);
  EXPECT_FALSE(fs::exists(file.string() + ".partial"));
  nlohmann::json j = nlohmann::json::parse(std::ifstream(file));
  EXPECT_EQ(j["frame"], 12);
  EXPECT_EQ(j["restarts"], 3);
  EXPECT_EQ(j["camera"]["position"][2], 3.0);
  EXPECT_TRUE(j["message_is_error"]);
}

TEST_F(ViewerFiles, ScreenshotShowsWhatThePostSettingsShow) {
  Image image(16, 8);
  for (uint32_t y = 0; y < 8; ++y)
    for (uint32_t x = 0; x < 16; ++x) image.at(x, y) = {float((x * 7 + y * 3) % 5) * 0.2f, 0.1f * float(y), 0.5f};
  PostSettings post;
  post.display = {0.5f, ToneMapper::AcesFilmic};
  post.bilateral = true;
  post.bilateralParams = {2, 1.0f, 0.5f};
  const fs::path file = dir / "shot.png";
  saveScreenshot(file.string(), image, post);

  int w = 0, h = 0, n = 0;
  unsigned char* bytes = stbi_load(file.c_str(), &w, &h, &n, 3);
  ASSERT_NE(bytes, nullptr);
  ASSERT_EQ(w, 16);
  ASSERT_EQ(h, 8);
  const Image filtered = bilateralFilter(image, post.bilateralParams);
  int unfilteredDiffers = 0;
  for (size_t i = 0; i < filtered.pixels.size(); ++i) {
    Vec3 expected = toneMap(filtered.pixels[i], 0.5f, ToneMapper::AcesFilmic);
    Vec3 raw = toneMap(image.pixels[i], 0.5f, ToneMapper::AcesFilmic);
    EXPECT_EQ(bytes[3 * i], uint8_t(expected.x * 255.0f + 0.5f));
    unfilteredDiffers += bytes[3 * i] != uint8_t(raw.x * 255.0f + 0.5f);
  }
  EXPECT_GT(unfilteredDiffers, 0);
  stbi_image_free(bytes);
  EXPECT_THROW(saveScreenshot((dir / "shot.bmp").string(), image, post), std::runtime_error);
}

}  // namespace
}  // namespace candela
