#pragma once
// A folder of the fuzz process's own, removed at exit, for targets whose loaders read files by path.
//
// The folder is made in memory (/dev/shm) where there is one, unless TMPDIR names another: on a disk-backed /tmp,
// scene_file spent most of its time waiting for the file system (20,000 inputs: 109 s, of which 6 s on the CPU;
// in /dev/shm: 11 s, 2 s on the CPU). The loader still opens, checks and reads a real file by its path.
#include <fcntl.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <string_view>

namespace candela::fuzz {

// TMPDIR where it is set (the tests set it), otherwise /dev/shm where it can be written, otherwise the system's.
inline std::filesystem::path tempFolderRoot() {
  if (const char* chosen = std::getenv("TMPDIR"); chosen && *chosen) return chosen;
  std::error_code error;
  if (std::filesystem::is_directory("/dev/shm", error) && ::access("/dev/shm", W_OK | X_OK) == 0) return "/dev/shm";
  return std::filesystem::temp_directory_path();
}

inline void removePrivateFolder();

inline const std::filesystem::path& privateFolder() {
  static const std::filesystem::path folder = [] {
    std::string pattern = (tempFolderRoot() / "candela-fuzz-XXXXXX").string();
    if (!mkdtemp(pattern.data())) {
      std::perror("mkdtemp");
      std::abort();
    }
    return std::filesystem::path(pattern);
  }();
  // Registered once `folder` is complete, so that it runs before `folder` is destroyed: exit handlers and static
  // destructors run in the reverse order of their registration. (Registered inside the initialiser, it ran after,
  // on a destroyed path, and every folder was left behind.)
  static const bool removedAtExit = std::atexit(removePrivateFolder) == 0;
  (void)removedAtExit;
  return folder;
}

inline void removePrivateFolder() {
  std::error_code ignored;  // an exit handler must not throw
  std::filesystem::remove_all(privateFolder(), ignored);
}

// Writes `bytes` to `name` in the private folder, replacing what was there, and returns its path. The same file
// is reused for every input; nothing is synced, as the file only has to outlive this process's next read of it.
inline std::string writePrivateFile(const std::string& name, std::string_view bytes) {
  const std::string path = (privateFolder() / name).string();
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
  size_t done = 0;
  while (fd >= 0 && done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    done += size_t(n);
  }
  if (fd < 0 || done < bytes.size() || ::close(fd) != 0) {
    // An input the loader would read only in part would make its findings unreproducible.
    std::perror(path.c_str());
    std::abort();
  }
  return path;
}

}  // namespace candela::fuzz
