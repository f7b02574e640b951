// Material, environment and instance transform edits on the OptiX backend give the images that a rebuild with setScene
// gives.
#include <gtest/gtest.h>

#include "backends/optix/optix_backend.h"
#include "support/scene_edits.h"

namespace candela {
namespace {

std::unique_ptr<Backend> makeOptix() { return std::make_unique<OptixBackend>(); }

TEST(GpuSceneEdits, SetMaterialsGivesTheImageOfSetScene) { test::expectMaterialEditMatchesRebuild(makeOptix); }

TEST(GpuSceneEdits, SetEnvironmentGivesTheImageOfSetScene) { test::expectEnvironmentEditMatchesRebuild(makeOptix); }

TEST(GpuSceneEdits, SetInstanceTransformsGivesTheImageOfSetScene) {
  test::expectInstanceTransformEditMatchesRebuild(makeOptix);
}

}  // namespace
}  // namespace candela
