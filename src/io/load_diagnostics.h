#pragma once
#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace candela {

// `text` safe to print on a terminal: line ends become spaces (a message stays one line), and every byte that a
// terminal could take for a command is written as \xNN: control characters (escape sequences included), DEL,
// the C1 controls, the bidirectional-text overrides, and bytes that are not valid UTF-8. Printable ASCII and
// other valid UTF-8 (file names in any script) are kept. Escaping escaped text changes nothing.
std::string printableText(std::string_view text);

// A file that cannot be loaded. The message is one line that starts with the file, and the line or JSON path
// where the problem is when that is known: "scene.obj:12: face refers to vertex 40 of 32". It quotes file
// content and names only through printableText.
class LoadError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

[[noreturn]] void failLoad(const std::string& file, const std::string& what);
[[noreturn]] void failLoad(const std::string& file, size_t line, const std::string& what);

// Problems a load survives (a missing texture, an unsupported feature): each one line naming the file, made
// printable like LoadError's.
struct LoadWarnings {
  std::vector<std::string> messages;

  void add(const std::string& file, const std::string& what) { messages.push_back(printableText(file + ": " + what)); }
};

}  // namespace candela
