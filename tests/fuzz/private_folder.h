#pragma once
// A folder of the fuzz process's own, removed at exit, for targets whose loaders read files by path.
#include <stdlib.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

namespace candela::fuzz {

inline const std::filesystem::path& privateFolder() {
  static const std::filesystem::path folder = [] {
    std::string pattern = (std::filesystem::temp_directory_path() / "candela-fuzz-XXXXXX").string();
    if (!mkdtemp(pattern.data())) {
      std::perror("mkdtemp");
      std::abort();
    }
    std::atexit([] { std::filesystem::remove_all(privateFolder()); });
    return std::filesystem::path(pattern);
  }();
  return folder;
}

// Writes `bytes` to `name` in the private folder and returns its path.
inline std::string writePrivateFile(const std::string& name, std::string_view bytes) {
  const std::filesystem::path path = privateFolder() / name;
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(bytes.data(), std::streamsize(bytes.size()));
  return path.string();
}

}  // namespace candela::fuzz
