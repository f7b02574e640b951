// The scene file's `lights`: point, spot and directional lights, their defaults and their errors.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/loaders/obj/obj_loader.h"
#include "scene/loaders/scene_file.h"
#include "scene/scene_repair.h"
#include "scene/scene_test_files.h"

namespace candela {
namespace {

using test::TempFolder;

Scene loadModel(const std::string& path, LoadWarnings& warnings, SharedModelAssets&) { return loadObj(path, warnings); }

Scene loadWithLights(TempFolder& dir, const std::string& lights, LoadWarnings& warnings) {
  dir.write("t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  return loadSceneFile(dir.write("s.json", R"({"models": [{"file": "t.obj"}], "lights": )" + lights + "}"), &loadModel,
                       warnings);
}

std::string errorOf(const std::string& lights) {
  TempFolder dir;
  LoadWarnings warnings;
  try {
    loadWithLights(dir, lights, warnings);
  } catch (const LoadError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected a LoadError for " << lights;
  return {};
}

TEST(SceneFileLights, PointSpotAndDirectional) {
  TempFolder dir;
  LoadWarnings warnings;
  Scene s = loadWithLights(dir, R"([
      {"type": "point", "position": [1, 2, 3], "color": [1, 0.5, 0.25], "intensity": 4},
      {"type": "spot", "position": [0, 5, 0], "target": [0, 0, 0], "inner_angle_degrees": 10,
       "outer_angle_degrees": 30},
      {"type": "directional", "direction": [0, -2, 0], "intensity": 2}])",
                           warnings);
  ASSERT_EQ(s.punctualLights.size(), 3u);
  EXPECT_TRUE(warnings.messages.empty());
  const PunctualLight &point = s.punctualLights[0], &spot = s.punctualLights[1], &sun = s.punctualLights[2];
  EXPECT_EQ(point.type, PunctualLightType::Point);
  EXPECT_FLOAT_EQ(point.position.z, 3.0f);
  EXPECT_FLOAT_EQ(point.intensity.x, 4.0f);
  EXPECT_FLOAT_EQ(point.intensity.z, 1.0f);
  EXPECT_EQ(spot.type, PunctualLightType::Spot);
  EXPECT_FLOAT_EQ(spot.direction.y, -1.0f);
  EXPECT_NEAR(spot.cosInner, std::cos(10.0f * kPi / 180.0f), 1e-6f);
  EXPECT_NEAR(spot.cosOuter, std::cos(30.0f * kPi / 180.0f), 1e-6f);
  EXPECT_FLOAT_EQ(spot.intensity.y, 1.0f);  // intensity and colour default to 1
  EXPECT_EQ(sun.type, PunctualLightType::Directional);
  EXPECT_FLOAT_EQ(sun.direction.y, -1.0f);
  EXPECT_FLOAT_EQ(sun.intensity.x, 2.0f);
}

TEST(SceneFileLights, MistakesNameTheLightAndTheField) {
  EXPECT_NE(
      errorOf(R"([{"type": "area", "position": [0, 0, 0]}])").find("s.json: lights[0].type: unknown light type 'area'"),
      std::string::npos);
  EXPECT_NE(errorOf(R"([{"type": "point"}])").find("lights[0]: 'position' is missing"), std::string::npos);
  EXPECT_NE(errorOf(R"([{"type": "spot", "position": [0, 1, 0], "direction": [0, -1, 0], "target": [0, 0, 0]}])")
                .find("lights[0]: give either 'direction' or 'target'"),
            std::string::npos);
  EXPECT_NE(errorOf(R"([{"type": "directional", "direction": [0, 0, 0]}])").find("has no length"), std::string::npos);
  EXPECT_NE(errorOf(R"([{"type": "point", "position": [0, 1, 0], "intensity": -1}])").find("lights[0].intensity"),
            std::string::npos);
  EXPECT_NE(errorOf(R"([{"type": "spot", "position": [0, 1, 0], "direction": [0, -1, 0], "inner_angle_degrees": 50,
                        "outer_angle_degrees": 30}])")
                .find("lights[0].inner_angle_degrees"),
            std::string::npos);
}

TEST(SceneFileLights, RepairDropsLightsOutOfRangeAndClampsIntensity) {
  TempFolder dir;
  LoadWarnings warnings;
  Scene s = loadWithLights(dir, R"([{"type": "point", "position": [1e20, 0, 0]},
                                    {"type": "point", "position": [0, 1, 0], "intensity": 1e30}])",
                           warnings);
  repairScene(s, "s.json", warnings);
  ASSERT_EQ(s.punctualLights.size(), 1u);
  EXPECT_EQ(s.punctualLights[0].intensity.x, kMaxRadiance);
  ASSERT_EQ(warnings.messages.size(), 2u);
  EXPECT_NE(warnings.messages[0].find("1 punctual lights dropped"), std::string::npos);
  EXPECT_NE(warnings.messages[1].find("intensity of 1 punctual lights is clamped"), std::string::npos);
}

}  // namespace
}  // namespace candela
