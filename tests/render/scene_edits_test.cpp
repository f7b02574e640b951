// Material, environment and instance transform edits on the CPU backend (Backend::setMaterials, setEnvironment,
// setInstanceTransforms) give the images that a rebuild with setScene gives; material edits that the light table
// or the tangents depend on are refused.
#include <gtest/gtest.h>

#include "backends/cpu/cpu_backend.h"
#include "scene/builtin_scenes.h"
#include "scene/flat_scene.h"
#include "support/scene_edits.h"

namespace candela {
namespace {

std::unique_ptr<Backend> makeCpu() { return std::make_unique<CpuBackend>(); }

TEST(CpuSceneEdits, SetMaterialsGivesTheImageOfSetScene) { test::expectMaterialEditMatchesRebuild(makeCpu); }

TEST(CpuSceneEdits, SetEnvironmentGivesTheImageOfSetScene) { test::expectEnvironmentEditMatchesRebuild(makeCpu); }

TEST(CpuSceneEdits, SetInstanceTransformsGivesTheImageOfSetScene) {
  test::expectInstanceTransformEditMatchesRebuild(makeCpu);
}

TEST(FlatSceneEdits, RefusesMaterialsThatTheLightTableOrTangentsDependOn) {
  const Scene scene = makeCornellBox();
  FlatScene flat = FlatScene::build(scene);
  std::vector<Material> brighter = scene.materials, normalMapped = scene.materials, fewer = scene.materials;
  for (Material& m : brighter) m.emission = m.emission * 2.0f;
  normalMapped[0].normalTexture = 0;
  fewer.pop_back();
  EXPECT_FALSE(flat.replaceMaterials(brighter));
  EXPECT_FALSE(flat.replaceMaterials(normalMapped));
  EXPECT_FALSE(flat.replaceMaterials(fewer));
  EXPECT_EQ(flat.materials[0].normalTexture, kNoTexture);  // nothing changed

  std::vector<Material> cutOut = scene.materials;
  cutOut[0].doubleSided = 0;
  EXPECT_TRUE(flat.replaceMaterials(cutOut));
  EXPECT_TRUE(flat.hasCutouts);
  EXPECT_TRUE(flat.replaceMaterials(scene.materials));
  EXPECT_FALSE(flat.hasCutouts);
}

}  // namespace
}  // namespace candela
