// A scene cache file passes its checksum whenever its writer computed one: finite but absurd values in it must
// meet the same repair and limits as a model loaded with them.
#include <gtest/gtest.h>

#include "app/scene_loading.h"
#include "scene/cache/scene_cache.h"
#include "scene/scene_repair.h"
#include "scene/scene_test_files.h"

namespace candela {
namespace {

using test::TempFolder;

constexpr const char* kTwoTriangles =
    "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 5 0 0\nv 6 0 0\nv 5 1 0\nusemtl glow\nf 1 2 3\nf 4 5 6\n";

// The model through loadScene with the scene cache of `folder`.
Scene loadCached(const TempFolder& folder, const std::string& model) {
  SceneLoadOptions options;
  options.cache = {true, folder.file("cache")};
  options.printWarnings = false;
  return loadScene(model, options);
}

TEST(SceneCacheValues, CraftedFiniteValuesAreRepairedAsInALoadedModel) {
  TempFolder folder;
  folder.write("m.mtl", "newmtl glow\nKd 0.5 0.5 0.5\nKe 1 1 1\n");
  const std::string model = folder.write("model.obj", kTwoTriangles);
  loadCached(folder, model);  // writes the cache
  const std::string cacheFile = sceneCacheFile(folder.file("cache"), model);
  CachedScene cached;
  ASSERT_EQ(readSceneCache(cacheFile, model, cached), SceneCacheRead::Hit);
  cached.scene.materials[0].emission = {1e30f, 1e30f, 1e30f};
  cached.scene.meshes[0].positions[cached.scene.meshes[0].indices[0]] = {3e38f, 0, 0};
  writeSceneCache(cacheFile, model, cached.scene, cached.warnings);
  ASSERT_EQ(readSceneCache(cacheFile, model, cached), SceneCacheRead::Hit);

  const Scene s = loadCached(folder, model);
  ASSERT_EQ(s.materials.size(), 1u);
  EXPECT_EQ(s.materials[0].emission.x, kMaxRadiance);
  EXPECT_EQ(s.triangleCount(), 1u) << "the triangle with a vertex at 3e38 is dropped";

  // The same values in the model itself meet the same fate.
  folder.write("m.mtl", "newmtl glow\nKd 0.5 0.5 0.5\nKe 1e30 1e30 1e30\n");
  const std::string loaded = folder.write("loaded.obj",
                                          "mtllib m.mtl\nv 3e38 0 0\nv 1 0 0\nv 0 1 0\nv 5 0 0\nv 6 0 0\nv 5 1 0\n"
                                          "usemtl glow\nf 1 2 3\nf 4 5 6\n");
  SceneLoadOptions fresh;
  fresh.printWarnings = false;
  const Scene l = loadScene(loaded, fresh);
  EXPECT_EQ(l.materials[0].emission.x, s.materials[0].emission.x);
  EXPECT_EQ(l.triangleCount(), s.triangleCount());
}

}  // namespace
}  // namespace candela
