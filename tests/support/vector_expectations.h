#pragma once
#include <gtest/gtest.h>

#include "core/math.h"

namespace candela::test {

// Each component of `a` within `tolerance` of `b`'s.
inline void expectNear(Vec3 a, Vec3 b, float tolerance = 1e-5f) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

}  // namespace candela::test
