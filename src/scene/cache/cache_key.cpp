#include "scene/cache/cache_key.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <xxhash.h>

#include <algorithm>
#include <cerrno>
#include <filesystem>

namespace candela {

namespace {

// Bumped whenever the layout of a cache file changes.
// 2: textures wrap per axis, cameras, vertex colours; 3: file states; 4: orthographic cameras, image shift;
// 5: animations; 6: mix materials; 7: materials' volume absorption; 8: the scene's camera index, skins and morph
// targets; 9: eight joints per vertex, morph targets' tangent deltas and iridescent materials; 10: participating
// media, the instances' medium interfaces, the camera's medium and the interface material; 11: grid media;
// 12: diffuse transmission and subsurface media; 13: hair materials; 14: grid media's temperatures; 15: curves
constexpr uint32_t kCacheFormatVersion = 15;

std::string absolutePath(const std::string& path) {
  std::error_code ec;
  std::filesystem::path p = std::filesystem::absolute(path, ec);
  return (ec ? std::filesystem::path(path) : p).lexically_normal().string();
}

void writeState(BinaryWriter& out, const FileState& s) {
  out.value(uint8_t(s.exists));
  out.value(s.size);
  out.value(s.modifiedNs);
  out.value(s.changedNs);
  out.value(s.inode);
  out.value(s.device);
  out.value(s.contentHash);
}

void readState(BinaryReader& in, FileState& s) {
  uint8_t exists = 0;
  in.value(exists);
  in.value(s.size);
  in.value(s.modifiedNs);
  in.value(s.changedNs);
  in.value(s.inode);
  in.value(s.device);
  in.value(s.contentHash);
  s.exists = exists != 0;
}

constexpr uint64_t kStateBytes = 1 + 6 * sizeof(uint64_t);

int64_t nanoseconds(const timespec& t) { return int64_t(t.tv_sec) * 1000000000 + t.tv_nsec; }

// XXH3 of a small file's contents; 0 when it cannot be read whole (the other fields then decide).
uint64_t contentHash(int fd, uint64_t size) {
  std::vector<char> bytes(size_t(size) + 1);  // a byte more than fstat said, to notice a file that grew since
  size_t got = 0;
  while (got < bytes.size()) {
    const ssize_t n = ::read(fd, bytes.data() + got, bytes.size() - got);
    if (n == 0) break;
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return 0;
    got += size_t(n);
  }
  return got == size ? XXH3_64bits(bytes.data(), got) : 0;
}

}  // namespace

FileState fileState(const std::string& path) {
  // The numbers and the contents come from one open file, so that they describe the same file even when it is
  // replaced meanwhile. A folder or a device reads no contents.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  struct stat st;
  if (fd < 0) {
    if (::stat(path.c_str(), &st) != 0) return {};  // missing; a file that exists but cannot be opened still counts
  } else if (::fstat(fd, &st) != 0) {
    ::close(fd);
    return {};
  }
  FileState s;
  s.exists = true;
  s.size = uint64_t(st.st_size);
  s.modifiedNs = nanoseconds(st.st_mtim);
  s.changedNs = nanoseconds(st.st_ctim);
  s.inode = uint64_t(st.st_ino);
  s.device = uint64_t(st.st_dev);
  if (fd >= 0) {
    if (S_ISREG(st.st_mode) && s.size < kHashedFileBytes) s.contentHash = contentHash(fd, s.size);
    ::close(fd);
  }
  return s;
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
