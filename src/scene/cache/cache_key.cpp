#include "scene/cache/cache_key.h"

#include <sys/stat.h>

#include <algorithm>
#include <filesystem>

namespace candela {

namespace {

// Bumped whenever the layout of a cache file changes.
constexpr uint32_t kCacheFormatVersion = 2;  // 2: textures wrap per axis; cameras; vertex colours

std::string absolutePath(const std::string& path) {
  std::error_code ec;
  std::filesystem::path p = std::filesystem::absolute(path, ec);
  return (ec ? std::filesystem::path(path) : p).lexically_normal().string();
}

void writeState(BinaryWriter& out, const FileState& s) {
  out.value(uint8_t(s.exists));
  out.value(s.size);
  out.value(s.modifiedNs);
}

void readState(BinaryReader& in, FileState& s) {
  uint8_t exists = 0;
  in.value(exists);
  in.value(s.size);
  in.value(s.modifiedNs);
  s.exists = exists != 0;
}

constexpr uint64_t kStateBytes = 1 + sizeof(uint64_t) + sizeof(int64_t);

}  // namespace

FileState fileState(const std::string& path) {
  struct stat st;
  if (::stat(path.c_str(), &st) != 0) return {};
  return {true, uint64_t(st.st_size), int64_t(st.st_mtim.tv_sec) * 1000000000 + st.st_mtim.tv_nsec};
}

CacheKey currentCacheKey(const std::string& modelPath, const std::vector<std::string>& inputFiles) {
  CacheKey key;
  key.formatVersion = kCacheFormatVersion;
  key.program = fileState("/proc/self/exe");
  key.files.push_back(absolutePath(modelPath));
  for (const std::string& f : inputFiles) {
    std::string p = absolutePath(f);
    if (std::find(key.files.begin(), key.files.end(), p) == key.files.end()) key.files.push_back(p);
  }
  for (const std::string& f : key.files) key.states.push_back(fileState(f));
  return key;
}

void writeCacheKey(BinaryWriter& out, const CacheKey& key) {
  out.value(key.formatVersion);
  writeState(out, key.program);
  out.value(uint64_t(key.files.size()));
  for (size_t i = 0; i < key.files.size(); ++i) {
    out.string(key.files[i]);
    writeState(out, key.states[i]);
  }
}

void readCacheKey(BinaryReader& in, CacheKey& key) {
  in.value(key.formatVersion);
  if (key.formatVersion != kCacheFormatVersion) return;  // a layout this build cannot read further
  readState(in, key.program);
  key.files.resize(size_t(in.count(sizeof(uint64_t) + kStateBytes)));
  key.states.resize(key.files.size());
  for (size_t i = 0; i < key.files.size(); ++i) {
    in.string(key.files[i]);
    readState(in, key.states[i]);
  }
}

bool cacheKeyHolds(const CacheKey& stored, const std::string& modelPath) {
  if (stored.formatVersion != kCacheFormatVersion || !(stored.program == fileState("/proc/self/exe")) ||
      stored.files.empty() || stored.files[0] != absolutePath(modelPath))
    return false;
  for (size_t i = 0; i < stored.files.size(); ++i)
    if (!(stored.states[i] == fileState(stored.files[i]))) return false;
  return true;
}

}  // namespace candela
