#include <gtest/gtest.h>
#include <stb/stb_image.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "app/interactive/viewer_files.h"
#include "app/scene_loading.h"
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
  camera.apertureRadius = 0.01f;
  RenderSettings settings;
  settings.width = 320;
  settings.height = 200;
  ViewerControls controls;
  controls.maxDepth = 5;
  Scene scene;
  scene.environment.radiance = {0.5f, 0.25f, 1.0f};
  scene.environment.intensity = 2.0f;
  scene.environment.rotationDegrees = 90.0f;
  const fs::path file = dir / "view.json";
  EXPECT_NE(writeViewFile(file.string(), "cornell-box", scene, camera, settings, controls), "");

  nlohmann::json j = nlohmann::json::parse(std::ifstream(file));
  EXPECT_FALSE(j.contains("models"));  // a built-in scene has no file
  EXPECT_EQ(j["camera"]["position"], nlohmann::json::array({1.0, 2.0, 3.0}));
  EXPECT_FLOAT_EQ(j["camera"]["target"][1].get<float>(), 0.5f);
  EXPECT_FLOAT_EQ(j["camera"]["fov_degrees"].get<float>(), 35.0f);
  EXPECT_FLOAT_EQ(j["camera"]["aperture_radius"].get<float>(), 0.01f);
  EXPECT_EQ(j["render"]["width"], 320);
  EXPECT_EQ(j["render"]["max_depth"], 5);
  EXPECT_FLOAT_EQ(j["environment"]["radiance"][2].get<float>(), 1.0f);
  EXPECT_FLOAT_EQ(j["environment"]["intensity"].get<float>(), 2.0f);
  EXPECT_FLOAT_EQ(j["environment"]["rotation_degrees"].get<float>(), 90.0f);
  EXPECT_THROW(writeViewFile((dir / "missing" / "view.json").string(), "x", scene, camera, settings, controls),
               std::runtime_error);
}

TEST_F(ViewerFiles, ViewFileNamesTheModelsItCameFrom) {
  Scene scene;
  CameraDescription camera;
  RenderSettings settings;
  ViewerControls controls;
  fs::create_directories(dir / "models");
  std::ofstream(dir / "models" / "box.obj") << "v 0 0 0\n";
  std::ofstream(dir / "models" / "scene.json") << R"({"models": [{"file": "box.obj", "transform": {"scale": 2}}]})";

  const fs::path fromObj = dir / "from-obj.json", fromJson = dir / "from-json.json";
  EXPECT_EQ(writeViewFile(fromObj.string(), (dir / "models" / "box.obj").string(), scene, camera, settings, controls),
            "");
  EXPECT_EQ(writeViewFile(fromJson.string(), (dir / "models" / "scene.json").string(), scene, camera, settings,
                          controls),
            "");
  const std::string box = fs::absolute(dir / "models" / "box.obj").lexically_normal().string();
  nlohmann::json a = nlohmann::json::parse(std::ifstream(fromObj));
  EXPECT_EQ(a["models"][0]["file"], box);
  nlohmann::json b = nlohmann::json::parse(std::ifstream(fromJson));
  EXPECT_EQ(b["models"][0]["file"], box);
  EXPECT_EQ(b["models"][0]["transform"]["scale"], 2);
}

TEST_F(ViewerFiles, AViewFileOfAModelLoadsBackWithItsView) {
  std::ofstream(dir / "tri.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  Scene scene = loadScene((dir / "tri.obj").string());
  scene.environment.radiance = {0.2f, 0.3f, 0.4f};
  scene.environment.intensity = 3.0f;
  CameraDescription camera;
  camera.eye = {0.5f, 0.5f, 4.0f};
  camera.target = {0.25f, 0.25f, 0.0f};
  camera.verticalFovDegrees = 30.0f;
  RenderSettings settings;
  settings.width = 300;
  settings.height = 100;
  ViewerControls controls;
  controls.maxDepth = 3;
  const fs::path file = dir / "view.json";
  ASSERT_EQ(writeViewFile(file.string(), (dir / "tri.obj").string(), scene, camera, settings, controls), "");

  Scene loaded = loadScene(file.string());
  EXPECT_EQ(loaded.triangleCount(), 1u);
  EXPECT_FALSE(loaded.cameraMissing);
  EXPECT_FLOAT_EQ(loaded.camera.eye.z, 4.0f);
  EXPECT_FLOAT_EQ(loaded.camera.target.x, 0.25f);
  EXPECT_FLOAT_EQ(loaded.camera.verticalFovDegrees, 30.0f);
  EXPECT_FLOAT_EQ(loaded.environment.radiance.y, 0.3f);
  EXPECT_FLOAT_EQ(loaded.environment.intensity, 3.0f);
  EXPECT_EQ(loaded.renderHints.width, 300u);
  EXPECT_EQ(loaded.renderHints.maxDepth, 3u);
}

TEST_F(ViewerFiles, StateFileAppearsWhole) {
  ViewerState state;
  state.frame = 12;
  state.restarts = 3;
  state.cameraPosition = {1, 2, 3};
  state.message = "could not open 'x'";
  state.messageIsError = true;
  state.openSceneText = "no-such-scene";
  state.openSceneFieldActive = true;
  const fs::path file = dir / "state.json";
  writeStateFile(file.string(), state);
  EXPECT_FALSE(fs::exists(file.string() + ".partial"));
  nlohmann::json j = nlohmann::json::parse(std::ifstream(file));
  EXPECT_EQ(j["frame"], 12);
  EXPECT_EQ(j["restarts"], 3);
  EXPECT_EQ(j["camera"]["position"][2], 3.0);
  EXPECT_TRUE(j["message_is_error"]);
  EXPECT_EQ(j["open_scene_text"], "no-such-scene");
  EXPECT_TRUE(j["open_scene_field_active"]);
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
  saveScreenshot(file.string(), image, Image(), post);

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
  EXPECT_THROW(saveScreenshot((dir / "shot.bmp").string(), image, Image(), post), std::runtime_error);
}

// With the emission the backend records, the bilateral filter keeps it apart, as the window's pass does: a bright
// emitter in the corner stays where it is instead of being smeared over its neighbours.
TEST_F(ViewerFiles, ScreenshotKeepsTheEmissionApartFromTheBilateralFilter) {
  Image image(16, 8), emission(16, 8);
  for (uint32_t y = 0; y < 8; ++y)
    for (uint32_t x = 0; x < 16; ++x) {
      image.at(x, y) = {0.1f * float((x + y) % 3), 0.2f, 0.3f};
      if (x < 4 && y < 4) {
        emission.at(x, y) = {8.0f, 6.0f, 4.0f};
        image.at(x, y) = image.at(x, y) + emission.at(x, y);
      }
    }
  PostSettings post;
  post.display = {-4.0f, ToneMapper::Clamp};  // the emitter's 8 shows as 0.5: nothing clipped
  post.bilateral = true;
  post.bilateralParams = {2, 1.0f, 5.0f};  // wide enough in range to smear the emitter without the emission apart
  const fs::path file = dir / "emitter.png";
  saveScreenshot(file.string(), image, emission, post);
  int w = 0, h = 0, n = 0;
  unsigned char* bytes = stbi_load(file.c_str(), &w, &h, &n, 3);
  ASSERT_NE(bytes, nullptr);
  ASSERT_EQ(w * h, 16 * 8);
  const Image expected = bilateralFilter(image, emission, post.bilateralParams),
              smeared = bilateralFilter(image, post.bilateralParams);
  int smearedDiffers = 0;
  for (size_t i = 0; i < expected.pixels.size(); ++i) {
    const Vec3 e = toneMap(expected.pixels[i], -4.0f, ToneMapper::Clamp);
    const Vec3 wrong = toneMap(smeared.pixels[i], -4.0f, ToneMapper::Clamp);
    EXPECT_EQ(bytes[3 * i], uint8_t(e.x * 255.0f + 0.5f));
    smearedDiffers += bytes[3 * i] != uint8_t(wrong.x * 255.0f + 0.5f);
  }
  stbi_image_free(bytes);
  EXPECT_GT(smearedDiffers, 0);
}

}  // namespace
}  // namespace candela
