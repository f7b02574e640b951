#pragma once
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

namespace candela {

// The extension of `path` with its dot, in lower case: ".obj" for "Scene.OBJ", "" when there is none.
inline std::string lowerCaseExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

}  // namespace candela
