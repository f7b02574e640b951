#include "io/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <climits>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <random>
#include <stdexcept>

namespace candela {

namespace fs = std::filesystem;

namespace {

// The temporaries not yet committed, in fixed storage that the signal handler can read without allocating.
// A slot is taken by setting `used` after its path is written, and released by clearing it.
constexpr int kSlots = 64;
struct TemporarySlot {
  std::atomic<bool> used{false};
  char path[PATH_MAX];
};
std::array<TemporarySlot, kSlots> temporaries;
std::mutex slotMutex;

// The signals whose default action ends the process: each removes the temporaries first. Where a signal is
// ignored (SIGHUP under nohup, SIGINT in a background job), it is left so: the process goes on and commits.
// SIGXFSZ and SIGXCPU come from the file-size and CPU-time limits (ulimit -f, -t): a write past the first ends the
// process in the middle of a temporary.
constexpr std::array<int, 7> kEndingSignals = {SIGINT, SIGTERM, SIGHUP, SIGPIPE, SIGQUIT, SIGXFSZ, SIGXCPU};
std::array<struct sigaction, kEndingSignals.size()> previousActions;

void removeTemporariesAndResignal(int signal) {
  for (TemporarySlot& slot : temporaries)
    if (slot.used.load()) ::unlink(slot.path);
  // Hand the signal to whatever handled it before (by default: end the process with it).
  for (size_t i = 0; i < kEndingSignals.size(); ++i)
    if (kEndingSignals[i] == signal) ::sigaction(signal, &previousActions[i], nullptr);
  ::raise(signal);
}

}  // namespace

void installTemporaryRemovalOnSignals() {
  static std::once_flag once;
  std::call_once(once, [] {
    struct sigaction action {};
    action.sa_handler = &removeTemporariesAndResignal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESETHAND;
    for (size_t i = 0; i < kEndingSignals.size(); ++i) {
      ::sigaction(kEndingSignals[i], nullptr, &previousActions[i]);
      if (previousActions[i].sa_handler != SIG_IGN) ::sigaction(kEndingSignals[i], &action, nullptr);
    }
  });
}

namespace {

int takeSlot(const std::string& path) {
  if (path.size() >= PATH_MAX) return -1;
  std::lock_guard lock(slotMutex);
  for (int i = 0; i < kSlots; ++i)
    if (!temporaries[size_t(i)].used.load()) {
      std::memcpy(temporaries[size_t(i)].path, path.c_str(), path.size() + 1);
      temporaries[size_t(i)].used.store(true);
      return i;
    }
  return -1;  // more than kSlots at once: still removed on failure, just not on a signal
}

void releaseSlot(int slot) {
  if (slot >= 0) temporaries[size_t(slot)].used.store(false);
}

[[noreturn]] void cannotWrite(const std::string& target, const std::string& why) {
  throw WriteError("cannot write '" + target + "': " + why);
}

std::string randomSuffix() {
  static std::atomic<unsigned> counter{0};
  std::random_device device;
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%08x%04x", device(), counter.fetch_add(1) & 0xffff);
  return buffer;
}

}  // namespace

std::string checkAtomicTarget(const std::string& target) {
  std::error_code ec;
  fs::path resolved = target;
  // Follow symbolic links, also to a file that does not exist yet.
  for (int hops = 0; fs::is_symlink(fs::symlink_status(resolved, ec)); ++hops) {
    if (hops == 40) cannotWrite(target, "too many levels of symbolic links");
    fs::path next = fs::read_symlink(resolved, ec);
    if (ec) cannotWrite(target, ec.message());
    resolved = next.is_absolute() ? next : resolved.parent_path() / next;
  }
  const fs::file_status status = fs::status(resolved, ec);
  if (fs::exists(status) && !fs::is_regular_file(status))
    cannotWrite(target, resolved.string() == target ? "it is not a regular file"
                                                    : "it leads to '" + resolved.string() + "', not a regular file");
  if (fs::exists(status) && ::access(resolved.c_str(), W_OK) != 0) cannotWrite(target, std::strerror(errno));
  fs::path folder = resolved.parent_path();
  if (folder.empty()) folder = ".";
  if (!fs::is_directory(folder, ec))
    cannotWrite(target,
                "directory '" + folder.string() + "'" +
                    (ec && ec != std::errc::no_such_file_or_directory ? ": " + ec.message() : " does not exist"));
  if (::access(folder.c_str(), W_OK) != 0) cannotWrite(target, "directory '" + folder.string() + "' is not writable");
  return resolved.string();
}

AtomicFile::AtomicFile(const std::string& target) : target_(target), resolved_(checkAtomicTarget(target)) {
  installTemporaryRemovalOnSignals();
  // A replaced file keeps its permissions; a new one gets those of any new file (0666 less the umask).
  struct stat existing {};
  const bool exists = ::stat(resolved_.c_str(), &existing) == 0;
  int fd = -1;
  for (int attempt = 0; fd < 0 && attempt < 16; ++attempt) {
    temporary_ = resolved_ + ".tmp-" + randomSuffix();
    slot_ = takeSlot(temporary_);
    fd = ::open(temporary_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0) {
      const int error = errno;
      releaseSlot(slot_);
      slot_ = -1;
      if (error != EEXIST) cannotWrite(target_, std::strerror(error));
    }
  }
  if (fd < 0) cannotWrite(target_, "no unused temporary file name");
  if (exists && ::fchmod(fd, existing.st_mode & 07777) != 0) {
    const int error = errno;
    ::close(fd);
    discard();
    cannotWrite(target_, std::strerror(error));
  }
  stream_ = ::fdopen(fd, "wb");
  if (!stream_) {
    const int error = errno;
    ::close(fd);
    discard();
    cannotWrite(target_, std::strerror(error));
  }
}

AtomicFile::~AtomicFile() {
  if (stream_) std::fclose(stream_);
  if (!committed_) discard();
}

void AtomicFile::discard() {
  if (!temporary_.empty()) ::unlink(temporary_.c_str());
  releaseSlot(slot_);
  slot_ = -1;
}

void AtomicFile::fail(const std::string& why) {
  if (stream_) std::fclose(stream_);
  stream_ = nullptr;
  discard();
  if (error_.empty()) error_ = why;
  cannotWrite(target_, error_);
}

void AtomicFile::write(const void* data, size_t size) {
  if (!stream_) fail(finished_ ? "written after it was finished" : error_);
  if (size > 0 && std::fwrite(data, 1, size, stream_) != size) fail(std::strerror(errno));
}

void AtomicFile::finish() {
  if (finished_) return;
  if (!stream_) fail(error_);
  if (std::ferror(stream_)) fail("a write failed");
  if (std::fflush(stream_) != 0) fail(std::strerror(errno));
  if (::fsync(::fileno(stream_)) != 0) fail(std::strerror(errno));
  std::FILE* stream = stream_;
  stream_ = nullptr;
  if (std::fclose(stream) != 0) {
    const int error = errno;
    discard();
    cannotWrite(target_, std::strerror(error));
  }
  finished_ = true;
}

void AtomicFile::commit() {
  finish();
  if (::rename(temporary_.c_str(), resolved_.c_str()) != 0) {
    const int error = errno;
    discard();
    cannotWrite(target_, std::strerror(error));
  }
  committed_ = true;
  releaseSlot(slot_);
  slot_ = -1;
  // The rename itself reaches the disk with the folder's entries.
  fs::path folder = fs::path(resolved_).parent_path();
  const int dir = ::open(folder.empty() ? "." : folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir >= 0) {
    ::fsync(dir);
    ::close(dir);
  }
}

void writeFileAtomically(const std::string& path, const void* data, size_t size) {
  AtomicFile file(path);
  file.write(data, size);
  file.commit();
}

}  // namespace candela
