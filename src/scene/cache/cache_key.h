#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "scene/cache/binary_stream.h"

namespace candela {

// What a file looked like: whether it existed, its size and its modification time in nanoseconds.
struct FileState {
  bool exists = false;
  uint64_t size = 0;
  int64_t modifiedNs = 0;

  bool operator==(const FileState&) const = default;
};
FileState fileState(const std::string& path);

// What a cached scene depends on: the cache format, the build of the program that wrote it (the size and
// modification time of its executable: scenes are stored in the build's own struct layout, and a changed
// loader must not be masked by what an older one cached) and the files the scene was read from, with absolute
// paths, the model first.
struct CacheKey {
  uint32_t formatVersion = 0;
  FileState program;
  std::vector<std::string> files;
  std::vector<FileState> states;
};

// The key of a model loaded now from `modelPath` and `inputFiles` (Scene::inputFiles).
CacheKey currentCacheKey(const std::string& modelPath, const std::vector<std::string>& inputFiles);

void writeCacheKey(BinaryWriter& out, const CacheKey& key);
void readCacheKey(BinaryReader& in, CacheKey& key);  // check in.ok() after

// Whether `stored` (read from a cache file) still describes the model at `modelPath`: same format, same
// program, the same model, and every file as it was.
bool cacheKeyHolds(const CacheKey& stored, const std::string& modelPath);

}  // namespace candela
