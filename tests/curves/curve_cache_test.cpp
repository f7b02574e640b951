// Curves through the scene cache: a pbrt scene of curves read back from the cache holds the same curves, and a
// cache file whose curves no loader gives (a hand-edited type) is not taken.
#include <gtest/gtest.h>

#include <cstring>

#include "app/scene_loading.h"
#include "scene/cache/scene_cache.h"
#include "scene/scene_test_files.h"

namespace candela::test {
namespace {

constexpr const char* kCurves =
    "LookAt 0 0 -5  0 0 0  0 1 0\nCamera \"perspective\"\nWorldBegin\n"
    "Shape \"curve\" \"string type\" \"ribbon\" \"point3 P\" [0 0 0 1 1 0 2 -1 0 3 0 0] \"normal N\" [0 0 -1 0 1 0]\n"
    "Shape \"curve\" \"string type\" \"ribbon\" \"string basis\" \"bspline\" \"point3 P\" [0 0 1 1 1 1 2 0 1 3 1 1 4 0 "
    "1]\n"
    "\"normal N\" [0 0 -1 0 0 -1 0 0 -1]\n";

template <class T>
bool sameBytes(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

TEST(CurveCache, CurvesComeBackFromTheCache) {
  TempFolder folder;
  const std::string model = folder.write("curves.pbrt", kCurves);
  SceneLoadOptions options;
  options.cache = {true, folder.file("cache")};
  options.printWarnings = false;
  const Scene loaded = loadScene(model, options);  // writes the cache
  ASSERT_EQ(loaded.meshes.size(), 1u);
  EXPECT_EQ(loaded.meshes[0].curveSegments.size(), 3u);

  const std::string cacheFile = sceneCacheFile(folder.file("cache"), model);
  CachedScene cached;
  ASSERT_EQ(readSceneCache(cacheFile, model, cached), SceneCacheRead::Hit);
  ASSERT_EQ(cached.scene.meshes.size(), 1u);
  const Mesh &a = loaded.meshes[0], &b = cached.scene.meshes[0];
  EXPECT_TRUE(sameBytes(a.curveVertices, b.curveVertices));
  EXPECT_TRUE(sameBytes(a.curveNormals, b.curveNormals));
  EXPECT_TRUE(sameBytes(a.curveSegments, b.curveSegments));

  cached.scene.meshes[0].curveSegments[1].type = CurveType(7);
  writeSceneCache(cacheFile, model, cached.scene, cached.warnings);
  EXPECT_EQ(readSceneCache(cacheFile, model, cached), SceneCacheRead::Invalid);
}

}  // namespace
}  // namespace candela::test
