// Punctual lights as next-event estimation sees them: the irradiance each kind sends to a point, and a spot's
// falloff between its cones.
#include <gtest/gtest.h>

#include <cmath>

#include "kernel/lights.h"

namespace candela {
namespace {

SceneView viewOf(const std::vector<PunctualLight>& lights) {
  SceneView view;
  view.punctualLights = lights.data();
  view.punctualLightCount = uint32_t(lights.size());
  return view;
}

TEST(PunctualLight, PointFallsOffWithTheSquareOfTheDistance) {
  PunctualLight light;
  light.position = {0, 4, 0};
  light.intensity = {8, 4, 2};
  std::vector<PunctualLight> lights{light};
  LightSample ls = samplePunctualLight(viewOf(lights), {0, 0, 0}, 0.3f);
  ASSERT_TRUE(ls.valid);
  EXPECT_FLOAT_EQ(ls.distance, 4.0f);
  EXPECT_FLOAT_EQ(ls.wi.y, 1.0f);
  EXPECT_FLOAT_EQ(ls.radiance.x, 0.5f);
  EXPECT_FLOAT_EQ(ls.radiance.z, 0.125f);
  EXPECT_FLOAT_EQ(ls.pdf, 1.0f);
}

TEST(PunctualLight, DirectionalArrivesFromAgainstItsDirectionFromInfinitelyFar) {
  PunctualLight light;
  light.type = PunctualLightType::Directional;
  light.direction = {0, -1, 0};
  light.intensity = {3, 3, 3};
  std::vector<PunctualLight> lights{light};
  LightSample ls = samplePunctualLight(viewOf(lights), {5, 0, -7}, 0.9f);
  ASSERT_TRUE(ls.valid);
  EXPECT_GE(ls.distance, kInf);
  EXPECT_FLOAT_EQ(ls.wi.y, 1.0f);
  EXPECT_FLOAT_EQ(ls.radiance.x, 3.0f);
}

TEST(PunctualLight, SpotIsFullInsideItsInnerConeDarkOutsideItsOuterAndSmoothBetween) {
  PunctualLight spot;
  spot.type = PunctualLightType::Spot;
  spot.position = {0, 1, 0};
  spot.direction = {0, -1, 0};
  spot.intensity = {1, 1, 1};
  spot.cosInner = std::cos(20.0f * kPi / 180.0f);
  spot.cosOuter = std::cos(40.0f * kPi / 180.0f);
  std::vector<PunctualLight> lights{spot};
  auto irradianceAtAngle = [&](float degrees) {
    float t = std::tan(degrees * kPi / 180.0f);
    LightSample ls = samplePunctualLight(viewOf(lights), {t, 0, 0}, 0.0f);
    return ls.valid ? ls.radiance.x * ls.distance * ls.distance : 0.0f;  // the falloff alone
  };
  EXPECT_FLOAT_EQ(irradianceAtAngle(0.0f), 1.0f);
  EXPECT_FLOAT_EQ(irradianceAtAngle(19.0f), 1.0f);
  EXPECT_EQ(irradianceAtAngle(41.0f), 0.0f);
  float previous = 1.0f;
  for (float degrees = 21.0f; degrees < 40.0f; degrees += 1.0f) {
    float f = irradianceAtAngle(degrees);
    EXPECT_LT(f, previous) << degrees;
    EXPECT_GT(f, 0.0f) << degrees;
    previous = f;
  }
  EXPECT_NEAR(spotFalloff(spot, 0.5f * (spot.cosInner + spot.cosOuter)), 0.5f, 1e-6f);
}

TEST(PunctualLight, EachOfSeveralIsPickedWithEqualProbability) {
  std::vector<PunctualLight> lights(4);
  for (size_t i = 0; i < lights.size(); ++i) lights[i].position = {float(i), 10, 0};
  int picks[4] = {};
  for (int k = 0; k < 4000; ++k) {
    LightSample ls = samplePunctualLight(viewOf(lights), {0, 0, 0}, (float(k) + 0.5f) / 4000.0f);
    ASSERT_FLOAT_EQ(ls.pdf, 0.25f);
    ++picks[ls.lightIndex];
  }
  for (int p : picks) EXPECT_EQ(p, 1000);
  EXPECT_EQ(samplePunctualLight(viewOf(lights), {0, 0, 0}, 0.99999994f).lightIndex, 3u);
}

}  // namespace
}  // namespace candela
