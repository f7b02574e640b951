#include <gtest/gtest.h>

#include "kernel/camera.h"

namespace candela {
namespace {

float angleBetween(Vec3 a, Vec3 b) { return acosf(clampf(dot(normalize(a), normalize(b)), -1.0f, 1.0f)); }

TEST(Camera, CentreRayLooksAtTheTarget) {
  Camera c = Camera::lookAt({1, 2, 3}, {1, 2, 10}, {0, 1, 0}, 40.0f, 1.5f);
  Ray r = c.generateRay(150.0f, 50.0f, 300, 100);
  EXPECT_NEAR(r.direction.x, 0.0f, 1e-6f);
  EXPECT_NEAR(r.direction.y, 0.0f, 1e-6f);
  EXPECT_NEAR(r.direction.z, 1.0f, 1e-6f);
  EXPECT_EQ(r.origin.y, 2.0f);
  EXPECT_NEAR(length(r.direction), 1.0f, 1e-6f);
}

TEST(Camera, EdgesSpanTheFieldOfView) {
  const float fov = 40.0f, aspect = 2.0f;
  Camera c = Camera::lookAt({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, fov, aspect);
  Vec3 forward{0, 0, -1};
  Ray top = c.generateRay(100.0f, 0.0f, 200, 100), bottom = c.generateRay(100.0f, 100.0f, 200, 100);
  EXPECT_NEAR(angleBetween(top.direction, forward) * 180.0f / kPi, fov / 2, 1e-3f);
  EXPECT_GT(top.direction.y, 0.0f) << "row 0 is the top of the image";
  EXPECT_LT(bottom.direction.y, 0.0f);
  Ray right = c.generateRay(200.0f, 50.0f, 200, 100);
  float expected = atanf(aspect * tanf(fov / 2 * kPi / 180.0f)) * 180.0f / kPi;
  EXPECT_NEAR(angleBetween(right.direction, forward) * 180.0f / kPi, expected, 1e-3f);
  EXPECT_GT(right.direction.x, 0.0f) << "looking down -z with +y up, image right is +x";
}

}  // namespace
}  // namespace candela
