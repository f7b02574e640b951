#include "scene/loaders/obj_text_source.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <vector>

#include "scene/loaders/load_diagnostics.h"

namespace candela {

namespace {

// The length of `piece` up to and including its last '\n'; 0 when it has none.
size_t wholeLines(std::string_view piece) {
  size_t last = piece.rfind('\n');
  return last == std::string_view::npos ? 0 : last + 1;
}

class MemoryText : public ObjTextSource {
 public:
  MemoryText(std::string_view text, size_t windowBytes) : text_(text), windowBytes_(std::max<size_t>(windowBytes, 1)) {}

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
  size_t position_ = 0;
};

class FileText : public ObjTextSource {
 public:
  FileText(std::string path, int fd, size_t windowBytes)
      : path_(std::move(path)), fd_(fd), buffer_(std::max<size_t>(windowBytes, 1)) {}
  ~FileText() override { ::close(fd_); }
  FileText(const FileText&) = delete;
  FileText& operator=(const FileText&) = delete;

  Window next() override {
    std::memmove(buffer_.data(), buffer_.data() + handedOver_, filled_ - handedOver_);
    filled_ -= handedOver_;
    offset_ += handedOver_;
    for (;;) {
      while (!atEnd_ && filled_ < buffer_.size()) {
        ssize_t n = ::read(fd_, buffer_.data() + filled_, buffer_.size() - filled_);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) failLoad(path_, std::string("read error: ") + std::strerror(errno));
        if (n == 0) atEnd_ = true;
        filled_ += size_t(n);
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
      ssize_t n = ::pread(fd_, text.data() + done, size - done, off_t(offset + done));
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) failLoad(path_, n == 0 ? std::string("changed while it was read") : std::string("read error: ") + std::strerror(errno));
      done += size_t(n);
    }
    return text;
  }

 private:
  std::string path_;
  int fd_;
  std::vector<char> buffer_;
  size_t filled_ = 0, handedOver_ = 0;
  uint64_t offset_ = 0;
  bool atEnd_ = false;
};

}  // namespace

std::unique_ptr<ObjTextSource> openObjTextFile(const std::string& path, size_t windowBytes) {
  int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) failLoad(path, std::string("cannot open: ") + std::strerror(errno));
  struct stat st {};
  const bool known = ::fstat(fd, &st) == 0;
  if (known && S_ISDIR(st.st_mode)) {
    ::close(fd);
    failLoad(path, "is a directory");
  }
  // No larger than the file, so that a small file costs no large buffer.
  size_t buffer = known ? std::min(windowBytes, size_t(std::max<off_t>(st.st_size, 1))) : windowBytes;
  return std::make_unique<FileText>(path, fd, buffer);
}

std::unique_ptr<ObjTextSource> objTextInMemory(std::string_view text, size_t windowBytes) {
  return std::make_unique<MemoryText>(text, windowBytes);
}

}  // namespace candela
