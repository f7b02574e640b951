#include "scene/loaders/obj/obj_text_source.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <vector>

#include "io/file_bytes.h"
#include "io/load_diagnostics.h"

namespace candela {

namespace {

// The length of `piece` up to and including its last '\n'; 0 when it has none.
size_t wholeLines(std::string_view piece) {
  size_t last = piece.rfind('\n');
  return last == std::string_view::npos ? 0 : last + 1;
}

// A UTF-8 byte order mark, which some editors write at the start of a text file: it is no part of the first
// statement (which would otherwise not be recognised, losing the first vertex).
size_t byteOrderMarkLength(std::string_view start) { return start.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0; }

class MemoryText : public ObjTextSource {
 public:
  MemoryText(std::string_view text, size_t windowBytes)
      : text_(text), windowBytes_(std::max<size_t>(windowBytes, 1)), position_(byteOrderMarkLength(text)) {}

  Window next() override {
    const size_t start = position_;
    if (text_.size() - start <= windowBytes_) {
      position_ = text_.size();
    } else {
      size_t length = wholeLines(text_.substr(start, windowBytes_));
      if (length == 0) {  // a line longer than the window: take all of it
        size_t newline = text_.find('\n', start + windowBytes_);
        length = newline == std::string_view::npos ? text_.size() - start : newline + 1 - start;
      }
      position_ = start + length;
    }
    return {text_.substr(start, position_ - start), start};
  }

  std::string reread(uint64_t offset, size_t size) override { return std::string(text_.substr(size_t(offset), size)); }

 private:
  std::string_view text_;
  size_t windowBytes_;
  size_t position_;
};

class FileText : public ObjTextSource {
 public:
  FileText(const std::string& path, size_t windowBytes)
      // No larger than the file, so that a small file costs no large buffer; 4 bytes at least, to see a whole
      // byte order mark.
      : file_(path), buffer_(std::max<uint64_t>(std::min<uint64_t>(windowBytes, file_.size()), 4)) {}

  Window next() override {
    std::memmove(buffer_.data(), buffer_.data() + handedOver_, filled_ - handedOver_);
    filled_ -= handedOver_;
    offset_ += handedOver_;
    for (;;) {
      while (!atEnd_ && filled_ < buffer_.size()) {
        // No further than the size the file had when it was opened: one that grows is not followed without end.
        uint64_t left = file_.size() - std::min(file_.size(), offset_ + filled_);
        size_t wanted = size_t(std::min<uint64_t>(buffer_.size() - filled_, left));
        ssize_t n = ::read(file_.descriptor(), buffer_.data() + filled_, wanted);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) failLoad(file_.path(), std::string("read error: ") + std::strerror(errno));
        if (n == 0) atEnd_ = true;
        filled_ += size_t(n);
      }
      if (offset_ == 0 && handedOver_ == 0 && byteOrderMarkLength({buffer_.data(), filled_}) > 0) {
        handedOver_ = byteOrderMarkLength({buffer_.data(), filled_});
        return next();
      }
      std::string_view data(buffer_.data(), filled_);
      handedOver_ = atEnd_ ? filled_ : wholeLines(data);
      if (handedOver_ > 0 || atEnd_) return {data.substr(0, handedOver_), offset_};
      buffer_.resize(2 * buffer_.size());  // one line fills the window
    }
  }

  std::string reread(uint64_t offset, size_t size) override {
    std::string text(size, '\0');
    size_t done = 0;
    while (done < size) {
      ssize_t n = ::pread(file_.descriptor(), text.data() + done, size - done, off_t(offset + done));
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0)
        failLoad(file_.path(), n == 0 ? std::string("changed while it was read")
                                      : std::string("read error: ") + std::strerror(errno));
      done += size_t(n);
    }
    return text;
  }

 private:
  InputFile file_;
  std::vector<char> buffer_;
  size_t filled_ = 0, handedOver_ = 0;
  uint64_t offset_ = 0;
  bool atEnd_ = false;
};

}  // namespace

std::unique_ptr<ObjTextSource> openObjTextFile(const std::string& path, size_t windowBytes) {
  return std::make_unique<FileText>(path, windowBytes);
}

std::unique_ptr<ObjTextSource> objTextInMemory(std::string_view text, size_t windowBytes) {
  return std::make_unique<MemoryText>(text, windowBytes);
}

}  // namespace candela
