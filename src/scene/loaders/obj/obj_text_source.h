#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

namespace candela {

// OBJ text handed over one window of whole lines at a time, so that a large file is read once and never held
// in memory whole.
class ObjTextSource {
 public:
  struct Window {
    std::string_view text;  // whole lines (the input's last line may lack a line end); empty at the end
    uint64_t offset = 0;    // of text's first byte in the input
  };

  virtual ~ObjTextSource() = default;
  // The next window, valid until the following call.
  virtual Window next() = 0;
  // `size` bytes from `offset` once more (to look at a piece again after the whole input has been read).
  virtual std::string reread(uint64_t offset, size_t size) = 0;
};

// A file, read in windows of about `windowBytes` (more where a line is longer), opened as InputFile
// (file_bytes.h) does: a regular file no larger than the limit. Throws LoadError naming the file when it cannot
// be opened or read. Both sources skip a UTF-8 byte order mark at the start; offsets still count its bytes.
std::unique_ptr<ObjTextSource> openObjTextFile(const std::string& path, size_t windowBytes);

// Text in memory, which must outlive the source.
std::unique_ptr<ObjTextSource> objTextInMemory(std::string_view text, size_t windowBytes);

}  // namespace candela
