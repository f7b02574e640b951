#pragma once
#include <cstdio>
#include <memory>
#include <optional>
#include <streambuf>
#include <string>
#include <string_view>
#include <vector>

namespace candela {

// The stream tinyobjloader reads OBJ text through, from a file or from memory. While handing the text over it
// checks the numbers of "v", "vn" and "vt" lines, which the parser would silently read as 0 when they are not
// numbers ("nan", "1.#IND"), and keeps the first such line. It also turns "vw" lines (tinyobjloader's skin-weight
// extension, which converts unchecked floats to int) into comments before the parser sees them; candela has no
// use for skin weights.
class ObjTextBuffer : public std::streambuf {
 public:
  static std::unique_ptr<ObjTextBuffer> openFile(const std::string& path);  // null when it cannot be opened
  explicit ObjTextBuffer(std::string_view text);
  ~ObjTextBuffer() override;

  std::optional<size_t> firstLineWithBadNumber() const { return badLine_; }
  std::optional<size_t> firstSkippedLine() const { return skippedLine_; }
  bool readFailed() const { return readFailed_; }

 protected:
  int_type underflow() override;

 private:
  ObjTextBuffer() = default;
  void scan(char* begin, char* end);

  std::FILE* file_ = nullptr;
  std::vector<char> chunk_;
  bool readFailed_ = false;

  enum class State { LineStart, Keyword, Numbers, Rest } state_ = State::LineStart;
  char keyword_[3] = {0, 0, 0};
  int keywordLength_ = 0;
  size_t line_ = 1;
  bool previousWasSpace_ = false;  // the last character of the previous chunk
  std::optional<size_t> badLine_;
  std::optional<size_t> skippedLine_;
  size_t carryStart_ = 0, carrySize_ = 0;  // the start of a line that continues past the chunk handed over
};

}  // namespace candela
