#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "scene/cache/binary_stream.h"

namespace candela {

// What a file looked like: whether it existed, its size, its modification and inode change times in
// nanoseconds, the inode and device numbers, and for files under kHashedFileBytes a hash of the contents.
//
// The modification time alone misses a same-size replacement that keeps it (`cp -p`, `rsync -t`, `touch -r`);
// the change time cannot be set from user space, and a replacement under a new name that is then renamed
// gets a new inode. Two writes of a small file within one tick of the file system's clock (a few milliseconds
// on Linux) can leave every number alike, which the content hash catches; large files (models of many MB)
// are not read again for it, since hashing them would cost much of what the cache saves.
struct FileState {
  bool exists = false;
  uint64_t size = 0;
  int64_t modifiedNs = 0;
  int64_t changedNs = 0;
  uint64_t inode = 0;
  uint64_t device = 0;
  uint64_t contentHash = 0;  // XXH3 of the contents for files under kHashedFileBytes, else 0

  bool operator==(const FileState&) const = default;
};
constexpr uint64_t kHashedFileBytes = 1 << 20;
FileState fileState(const std::string& path);

// What a cached scene depends on: the cache format, the build of the program that wrote it (the state of its
// executable: scenes are stored in the build's own struct layout, and a changed loader must not be masked by
// what an older one cached) and the files the scene was read from, with absolute
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
