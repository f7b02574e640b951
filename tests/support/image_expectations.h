#pragma once
#include <gtest/gtest.h>

#include <cmath>

#include "image/image.h"

namespace candela::test {

// A backend updated in place must render `updated` equal, bit for bit (red channel), to `rebuilt`, the image of a
// backend given the changed scene afresh; and the change must show: the pixels differ from `atRest` by more than
// `minimumChange` in all.
inline void expectRebuiltImageThatChanged(const Image& updated, const Image& rebuilt, const Image& atRest,
                                          double minimumChange) {
  double change = 0;
  for (uint32_t y = 0; y < updated.height; ++y)
    for (uint32_t x = 0; x < updated.width; ++x) {
      ASSERT_EQ(updated.at(x, y).x, rebuilt.at(x, y).x) << x << " " << y;
      change += std::fabs(updated.at(x, y).x - atRest.at(x, y).x);
    }
  EXPECT_GT(change, minimumChange);
}

}  // namespace candela::test
