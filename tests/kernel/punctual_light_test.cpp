// Punctual lights as next-event estimation sees them: the irradiance each kind sends to a point, a spot's
// falloff between its cones, and the power the power table weighs them by. How they are picked among the other
// lights: tests/scene/light_bvh_test.cpp.
#include <gtest/gtest.h>

#include <cmath>

#include "kernel/lights.h"

namespace candela {
namespace {

TEST(PunctualLight, PointFallsOffWithTheSquareOfTheDistance) {
  PunctualLight light;
  light.position = {0, 4, 0};
  light.intensity = {8, 4, 2};
  LightSample ls = samplePunctualLight(light, {0, 0, 0}, 0.25f);
  ASSERT_TRUE(ls.valid);
  EXPECT_TRUE(ls.isDelta);
  EXPECT_FLOAT_EQ(ls.distance, 4.0f);
  EXPECT_FLOAT_EQ(ls.wi.y, 1.0f);
  EXPECT_FLOAT_EQ(ls.radiance.x, 0.5f);
  EXPECT_FLOAT_EQ(ls.radiance.z, 0.125f);
  EXPECT_FLOAT_EQ(ls.pdf, 0.25f);
  EXPECT_FALSE(samplePunctualLight(light, {0, 0, 0}, 0.0f).valid);
}

TEST(PunctualLight, DirectionalArrivesFromAgainstItsDirectionFromInfinitelyFar) {
  PunctualLight light;
  light.type = PunctualLightType::Directional;
  light.direction = {0, -1, 0};
  light.intensity = {3, 3, 3};
  LightSample ls = samplePunctualLight(light, {5, 0, -7}, 1.0f);
  ASSERT_TRUE(ls.valid);
  EXPECT_TRUE(ls.isDelta);
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
  auto irradianceAtAngle = [&](float degrees) {
    float t = std::tan(degrees * kPi / 180.0f);
    LightSample ls = samplePunctualLight(spot, {t, 0, 0}, 1.0f);
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

// The power table weighs a point light by 4 pi I and a spot by what its cone and falloff let out: the
// integral of I falloff over the sphere, here by quadrature in cos(theta).
TEST(PunctualLight, PowerIsTheIntensityIntegratedOverTheSphere) {
  PunctualLight point;
  point.intensity = {2, 2, 2};
  EXPECT_NEAR(punctualLightPower(point), 4.0 * kPi * 2.0, 1e-4);
  PunctualLight spot = point;
  spot.type = PunctualLightType::Spot;
  spot.cosInner = std::cos(15.0f * kPi / 180.0f);
  spot.cosOuter = std::cos(50.0f * kPi / 180.0f);
  const int kSteps = 200000;
  double integral = 0.0;
  for (int i = 0; i < kSteps; ++i) {
    float cosTheta = -1.0f + 2.0f * (float(i) + 0.5f) / float(kSteps);
    integral += 2.0 * spotFalloff(spot, cosTheta) * (2.0 * kPi) * (2.0 / kSteps);  // I falloff dOmega
  }
  EXPECT_NEAR(punctualLightPower(spot), integral, 1e-3 * integral);
}

}  // namespace
}  // namespace candela
