#include "scene/cache/scene_cache.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <xxhash.h>

#include <atomic>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include "io/atomic_file.h"
#include "scene/cache/cache_key.h"
#include "scene/cache/cached_scene_validation.h"
#include "scene/cache/scene_serialization.h"

namespace candela {

namespace fs = std::filesystem;

namespace {

constexpr char kMagic[8] = {'c', 'a', 'n', 'd', 'e', 'l', 'a', 'S'};

using File = std::unique_ptr<std::FILE, int (*)(std::FILE*)>;

std::string environment(const char* name) {
  const char* v = std::getenv(name);
  return v ? v : "";
}

// The model's file name with anything unusual replaced, to make cache files recognisable.
std::string readableStem(const std::string& modelPath) {
  std::string stem = fs::path(modelPath).stem().string().substr(0, 40);
  for (char& c : stem)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.') c = '_';
  return stem;
}

}  // namespace

std::string defaultSceneCacheDirectory() {
  if (std::string dir = environment("CANDELA_CACHE_DIR"); !dir.empty()) return dir;
  if (std::string xdg = environment("XDG_CACHE_HOME"); fs::path(xdg).is_absolute())
    return (fs::path(xdg) / "candela").string();
  if (std::string home = environment("HOME"); !home.empty()) return (fs::path(home) / ".cache" / "candela").string();
  return {};
}

std::string sceneCacheFile(const std::string& directory, const std::string& modelPath) {
  std::error_code ec;
  std::string absolute = fs::absolute(modelPath, ec).lexically_normal().string();
  char hash[17];
  std::snprintf(hash, sizeof hash, "%016llx",
                static_cast<unsigned long long>(XXH3_64bits(absolute.data(), absolute.size())));
  return (fs::path(directory) / (readableStem(modelPath) + "-" + hash + ".scene")).string();
}

void writeSceneCache(const std::string& cacheFile, const std::string& modelPath, const Scene& scene,
                     const std::vector<std::string>& warnings) {
  std::error_code ec;
  fs::create_directories(fs::path(cacheFile).parent_path(), ec);
  AtomicFile file(cacheFile);
  {
    BinaryWriter out(file.stream());
    out.bytes(kMagic, sizeof kMagic);
    writeCacheKey(out, currentCacheKey(modelPath, scene.inputFiles));
    out.value(uint64_t(warnings.size()));
    for (const std::string& w : warnings) out.string(w);
    writeScene(out, scene);
    out.finish();
  }
  file.commit();
}

SceneCacheRead readSceneCache(const std::string& cacheFile, const std::string& modelPath, CachedScene& out,
                              std::string* problem) {
  // Opened without blocking, so that a FIFO in its place is found not to be a regular file below.
  const int fd = ::open(cacheFile.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return SceneCacheRead::Missing;
  File file(::fdopen(fd, "rb"), &std::fclose);
  if (!file) {
    ::close(fd);
    return SceneCacheRead::Missing;
  }
  struct stat st;
  if (::fstat(::fileno(file.get()), &st) != 0 || !S_ISREG(st.st_mode)) return SceneCacheRead::Damaged;
  BinaryReader in(file.get(), uint64_t(st.st_size));
  char magic[sizeof kMagic] = {};
  in.bytes(magic, sizeof magic);
  if (!in.ok() || std::memcmp(magic, kMagic, sizeof kMagic) != 0) return SceneCacheRead::Damaged;
  CacheKey key;
  readCacheKey(in, key);
  if (!in.ok()) return SceneCacheRead::Damaged;
  if (!cacheKeyHolds(key, modelPath)) return SceneCacheRead::Stale;
  CachedScene cached;
  cached.warnings.resize(size_t(in.count(sizeof(uint64_t))));
  for (std::string& w : cached.warnings) in.string(w);
  if (!readScene(in, cached.scene) || !in.checksumMatches()) return SceneCacheRead::Damaged;
  try {
    validateCachedScene(cached.scene);
  } catch (const std::exception& e) {
    if (problem) *problem = e.what();
    return SceneCacheRead::Invalid;
  }
  out = std::move(cached);
  return SceneCacheRead::Hit;
}

Scene loadThroughSceneCache(const std::string& path, const SceneCacheSettings& settings, LoadWarnings& warnings,
                            const std::function<Scene(LoadWarnings&)>& load) {
  const std::string directory = settings.directory.empty() ? defaultSceneCacheDirectory() : settings.directory;
  if (!settings.enabled || directory.empty()) return load(warnings);
  const std::string cacheFile = sceneCacheFile(directory, path);
  CachedScene cached;
  std::string problem;
  switch (readSceneCache(cacheFile, path, cached, &problem)) {
    case SceneCacheRead::Hit:
      warnings.messages.insert(warnings.messages.end(), cached.warnings.begin(), cached.warnings.end());
      return std::move(cached.scene);
    case SceneCacheRead::Damaged:
      warnings.add(cacheFile, "damaged scene cache ignored; the model is loaded afresh and cached again");
      break;
    case SceneCacheRead::Invalid:
      warnings.add(cacheFile,
                   "invalid scene cache ignored (" + problem + "); the model is loaded afresh and cached again");
      break;
    case SceneCacheRead::Missing:
    case SceneCacheRead::Stale: break;
  }
  // A model that changes while it loads is not cached: the cache would hold the old one under the new key.
  const FileState before = fileState(path);
  LoadWarnings fresh;
  Scene scene = load(fresh);
  try {
    if (fileState(path) == before) {
      validateCachedScene(scene);  // what the cache would refuse to read back is not written
      writeSceneCache(cacheFile, path, scene, fresh.messages);
    }
  } catch (const std::exception& e) {
    warnings.messages.push_back(std::string("scene cache not written: ") + e.what());
  }
  warnings.messages.insert(warnings.messages.end(), fresh.messages.begin(), fresh.messages.end());
  return scene;
}

}  // namespace candela
