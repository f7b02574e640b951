#pragma once
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace candela {

// A file that cannot be loaded. The message is one line that starts with the file, and the line or JSON path
// where the problem is when that is known: "scene.obj:12: face refers to vertex 40 of 32".
class LoadError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

[[noreturn]] void failLoad(const std::string& file, const std::string& what);
[[noreturn]] void failLoad(const std::string& file, size_t line, const std::string& what);

// Problems a load survives (a missing texture, an unsupported feature): each one line naming the file.
struct LoadWarnings {
  std::vector<std::string> messages;

  void add(const std::string& file, const std::string& what) { messages.push_back(file + ": " + what); }
};

}  // namespace candela
