#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace candela {

// One token of pbrt's scene format: a quoted string (quotes removed, escapes decoded), a bracket, or a bare word
// (a directive, a number, `true`/`false`).
struct PbrtToken {
  enum class Kind { Word, String, OpenBracket, CloseBracket, End };
  Kind kind = Kind::End;
  std::string text;
  size_t line = 0;
};

// Splits the text of one .pbrt file into tokens, with the line each starts on. `#` starts a comment that runs to
// the end of the line. Malformed text (an unterminated string, a line break inside one) throws LoadError naming
// `file` and the line.
class PbrtTokenizer {
 public:
  PbrtTokenizer(std::string file, std::string text);
  // The content of a file as readFileBytes gives it, taken over without a copy.
  PbrtTokenizer(std::string file, std::vector<uint8_t>&& bytes);
  PbrtTokenizer(const PbrtTokenizer&) = delete;  // text_ points into the object itself
  PbrtTokenizer& operator=(const PbrtTokenizer&) = delete;

  const PbrtToken& peek();
  PbrtToken next();
  const std::string& file() const { return file_; }
  size_t line() const { return line_; }

 private:
  void scan();

  std::string file_;
  std::vector<uint8_t> storage_;  // holds the text unless it came as a string
  std::string ownedText_;
  std::string_view text_;
  size_t pos_ = 0;
  size_t line_ = 1;
  PbrtToken lookahead_;
  bool haveLookahead_ = false;
};

}  // namespace candela
