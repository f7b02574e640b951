// Embree's errors as a user reads them: running out of memory while building the BVHs is said so, with the
// scene's size, rather than as an error number.
#include "backends/cpu/embree_errors.h"

#include <gtest/gtest.h>

namespace candela {
namespace {

TEST(EmbreeErrors, OutOfMemoryIsSaidSoWithTheSceneSize) {
  EXPECT_EQ(embreeFailure(RTC_ERROR_OUT_OF_MEMORY, "building a mesh BVH", {5000, 1600000000, 5000}),
            "not enough memory for Embree while building a mesh BVH: the scene has 5000 meshes of 1600000000 "
            "triangles in all and 5000 instances");
}

TEST(EmbreeErrors, OtherErrorsAreNamed) {
  EXPECT_EQ(embreeFailure(RTC_ERROR_INVALID_ARGUMENT, "building the instance BVH", {1, 1, 1}),
            "Embree failed while building the instance BVH (an invalid argument, error 2)");
}

}  // namespace
}  // namespace candela
