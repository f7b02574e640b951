#pragma once
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace candela::test {

// The folder of shared test scenes, or an empty path when this machine does not have it.
inline std::filesystem::path sharedScenes() {
  std::filesystem::path p = CANDELA_SHARED_SCENES;
  return std::filesystem::is_directory(p) ? p : std::filesystem::path();
}

#define CANDELA_REQUIRE_SHARED_SCENES(var)                           \
  const std::filesystem::path var = ::candela::test::sharedScenes(); \
  if (var.empty()) GTEST_SKIP() << "shared scenes not found at " << CANDELA_SHARED_SCENES

// A fresh folder under the system's temporary directory, removed again when the object goes.
class TempFolder {
 public:
  TempFolder() {
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = std::filesystem::temp_directory_path() /
            ("candela-" + std::string(info->test_suite_name()) + "-" + info->name() + "-" + std::to_string(::getpid()));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempFolder() { std::filesystem::remove_all(path_); }
  TempFolder(const TempFolder&) = delete;
  TempFolder& operator=(const TempFolder&) = delete;

  std::string write(const std::string& name, const std::string& content) const {
    std::filesystem::path p = path_ / name;
    std::filesystem::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << content;
    return p.string();
  }
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace candela::test
