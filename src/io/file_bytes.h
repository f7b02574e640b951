#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace candela {

// The largest file a loader reads (models, their buffers and textures, scene files, environment maps): a file
// that cannot be what it claims to be (a link to /dev/zero, a runaway export) is refused before it is read,
// rather than filling the memory. 8 GiB unless the command line raised or lowered it (--max-file-gib).
constexpr uint64_t kDefaultMaxInputFileBytes = uint64_t(8) << 30;
uint64_t maxInputFileBytes();
void setMaxInputFileBytes(uint64_t bytes);

// A file opened for reading, closed with the object. Only regular files are opened: a FIFO (opened without
// blocking, so that no writer is waited for), a device, a socket or a directory is refused, and so is a file
// larger than maxInputFileBytes(). Throws LoadError naming the file and why.
class InputFile {
 public:
  explicit InputFile(const std::string& path);
  ~InputFile();
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;

  int descriptor() const { return fd_; }
  uint64_t size() const { return size_; }  // when it was opened
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  int fd_ = -1;
  uint64_t size_ = 0;
};

// The whole content of a file opened as InputFile does; throws LoadError naming the file when it cannot be read.
std::vector<uint8_t> readFileBytes(const std::string& path);
// The same from a file already open, for a reader that checks its size first.
std::vector<uint8_t> readFileBytes(const InputFile& file);

}  // namespace candela
