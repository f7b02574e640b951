#pragma once
#include <functional>
#include <string>
#include <vector>

#include "io/load_diagnostics.h"
#include "scene/scene.h"

namespace candela {

// Whether loaded models (.obj, .gltf, .glb) go through the scene cache, and where it is.
struct SceneCacheSettings {
  bool enabled = false;
  std::string directory;  // empty: defaultSceneCacheDirectory()
};

// $CANDELA_CACHE_DIR, else $XDG_CACHE_HOME/candela, else $HOME/.cache/candela; empty when none is set.
std::string defaultSceneCacheDirectory();

// The cache file for the model at `modelPath`: named after it and a hash of its absolute path.
std::string sceneCacheFile(const std::string& directory, const std::string& modelPath);

// A cache file holds a loaded model, the warnings its load gave, and the key (cache_key.h) that says when it is
// out of date: the cache format, the program's build, and the size and modification time of every file the
// model was read from. It ends with a checksum of all of it.
struct CachedScene {
  Scene scene;
  std::vector<std::string> warnings;
};

// Writes the cache file atomically: into a temporary file in the same folder, which is then renamed, so that a
// reader sees the old file, the new one or none. Throws std::runtime_error when it cannot.
void writeSceneCache(const std::string& cacheFile, const std::string& modelPath, const Scene& scene,
                     const std::vector<std::string>& warnings);

enum class SceneCacheRead {
  Hit,      // `out` holds the model
  Missing,  // no cache file
  Stale,    // written by another build or format, or for files that have changed since
  Damaged,  // truncated or corrupted: the checksum or a count does not hold
  Invalid,  // whole, but the scene it holds is not one a loader gives (validateCachedScene): a hand-built file
};
// Reads a cache file, checking every count against the file's size before allocating, so that no file can
// crash the reader or make it allocate more than the file holds. For Invalid, `problem` (when given) receives
// what is wrong with the scene.
SceneCacheRead readSceneCache(const std::string& cacheFile, const std::string& modelPath, CachedScene& out,
                              std::string* problem = nullptr);

// Loads the model at `path` from the cache when it is there and up to date (its warnings are given again),
// else through `load`, writing the result to the cache. A damaged or invalid cache file is a warning and is
// replaced; failing to write one is a warning too, and so is a loaded scene that the cache would not read back.
Scene loadThroughSceneCache(const std::string& path, const SceneCacheSettings& settings, LoadWarnings& warnings,
                            const std::function<Scene(LoadWarnings&)>& load);

}  // namespace candela
