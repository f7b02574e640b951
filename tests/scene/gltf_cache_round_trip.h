#pragma once
#include <string>
#include <utility>

#include "scene/cache/scene_cache.h"
#include "scene/loaders/gltf/gltf_loader.h"
#include "scene/scene_test_files.h"

namespace candela::test {

// A glTF file as loaded, and scenes written as its scene cache and read back, as a second load of the file would.
class GltfCacheRoundTrip {
 public:
  GltfCacheRoundTrip(const TempFolder& folder, std::string path)
      : path_(std::move(path)), cache_(sceneCacheFile(folder.file("cache"), path_)) {
    LoadWarnings warnings;
    loaded_ = loadGltf(path_, warnings);
  }
  const Scene& loaded() const { return loaded_; }

  // Writes `scene` as the file's cached scene and reads it back into `read`.
  SceneCacheRead writeAndRead(const Scene& scene, CachedScene& read, std::string* problem = nullptr) const {
    writeSceneCache(cache_, path_, scene, {});
    return readSceneCache(cache_, path_, read, problem);
  }
  // Why a cache holding `scene` is not trusted, or "(trusted)".
  std::string refusal(const Scene& scene) const {
    CachedScene read;
    std::string problem;
    return writeAndRead(scene, read, &problem) == SceneCacheRead::Invalid ? problem : "(trusted)";
  }

 private:
  std::string path_, cache_;
  Scene loaded_;
};

}  // namespace candela::test
