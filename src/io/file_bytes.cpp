#include "io/file_bytes.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include "io/load_diagnostics.h"

namespace candela {

namespace {

std::atomic<uint64_t> maxBytes{kDefaultMaxInputFileBytes};

const char* kindOf(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

std::string gib(uint64_t bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g GiB", double(bytes) / double(uint64_t(1) << 30));
  return text;
}

std::string notRegular(const struct stat& st) {
  return std::string("is ") + kindOf(st.st_mode) + ", not a file that can be loaded";
}

}  // namespace

uint64_t maxInputFileBytes() { return maxBytes.load(std::memory_order_relaxed); }
void setMaxInputFileBytes(uint64_t bytes) { maxBytes.store(bytes, std::memory_order_relaxed); }

InputFile::InputFile(const std::string& path) : path_(path) {
  // A device is not even opened where that can be helped (opening some has effects: a tape rewinds, a modem
  // line is taken); the check after opening is the one that counts, as the path may change in between.
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) failLoad(path, notRegular(st));
  fd_ = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd_ < 0) failLoad(path, std::string("cannot open: ") + std::strerror(errno));
  std::string refusal;
  if (::fstat(fd_, &st) != 0)
    refusal = std::string("cannot read: ") + std::strerror(errno);
  else if (!S_ISREG(st.st_mode))
    refusal = notRegular(st);
  else if (uint64_t(st.st_size) > maxInputFileBytes())
    refusal = "is " + std::to_string(uint64_t(st.st_size)) + " bytes, larger than the " + gib(maxInputFileBytes()) +
              " a file may be (--max-file-gib raises the limit)";
  if (!refusal.empty()) {
    ::close(fd_);
    failLoad(path, refusal);
  }
  // A regular file never blocks; clearing the flag keeps reads ordinary for libraries handed the descriptor.
  ::fcntl(fd_, F_SETFL, ::fcntl(fd_, F_GETFL) & ~O_NONBLOCK);
  size_ = uint64_t(st.st_size);
}

InputFile::~InputFile() { ::close(fd_); }

std::vector<uint8_t> readFileBytes(const std::string& path) { return readFileBytes(InputFile(path)); }

std::vector<uint8_t> readFileBytes(const InputFile& file) {
  const std::string& path = file.path();
  // Exactly the size the file had when it was opened: a file that grows meanwhile is not followed without end.
  std::vector<uint8_t> bytes(size_t(file.size()));
  size_t done = 0;
  while (done < bytes.size()) {
    ssize_t n = ::read(file.descriptor(), bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) failLoad(path, std::string("read error: ") + std::strerror(errno));
    if (n == 0) failLoad(path, "became shorter while it was read");
    done += size_t(n);
  }
  return bytes;
}

}  // namespace candela
