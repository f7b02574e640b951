#pragma once
#include <cstddef>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace candela {

// What AtomicFile throws: one line, "cannot write '<target>': <why>".
class WriteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A file that is replaced whole or not at all. The bytes go to a new temporary file beside the target
// ("<name>.tmp-<random>", created exclusively, with the permissions a new file gets, or the target's when it
// exists); commit() checks that every byte reached the disk (flush, fsync, close) and only then renames it over
// the target. Until then the target is untouched, and a failure at any step removes the temporary: when the
// object is destroyed uncommitted, and on SIGINT, SIGTERM, SIGHUP, SIGPIPE, SIGQUIT, SIGXFSZ or SIGXCPU (the handlers
// are installed on first use, for the signals not ignored, and then let the signal end the process as before).
//
// A target that is a symbolic link is followed: the file it points to is replaced and the link kept. A target
// that exists and is not a regular file (a device such as /dev/full, a pipe, a folder) is refused, since it
// cannot be replaced atomically and writing into it could not be checked.
//
// Every failure throws WriteError.
class AtomicFile {
 public:
  explicit AtomicFile(const std::string& target);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  void write(const void* data, size_t size);
  // The open temporary file (null once finished or failed), for writers that take a FILE*; finish() checks its
  // error indicator.
  std::FILE* stream() { return stream_; }
  // Data on disk and the temporary closed; throws when any write, the flush, fsync or close failed.
  void finish();
  // finish(), then the rename over the target.
  void commit();

  const std::string& target() const { return target_; }

 private:
  [[noreturn]] void fail(const std::string& why);
  void discard();

  std::string target_;    // as the caller named it, for messages
  std::string resolved_;  // the file replaced: the target, or where its symbolic links lead
  std::string temporary_;
  std::FILE* stream_ = nullptr;
  std::string error_;  // the first failure; every later operation fails with it
  int slot_ = -1;      // in the table of temporaries the signal handler removes
  bool finished_ = false;
  bool committed_ = false;
};

// Where writing `target` would go (symbolic links followed); throws the same error as AtomicFile when the target
// exists and is not a regular file or not writable, or its folder does not exist or is not writable. For checks
// before a long render.
std::string checkAtomicTarget(const std::string& target);

// Installs the SIGINT, SIGTERM, SIGHUP, SIGPIPE, SIGQUIT, SIGXFSZ and SIGXCPU handlers that remove uncommitted
// temporaries, as the first AtomicFile does. A caller that installs handlers of its own calls it first and hands the
// signal on to these (the previous ones).
void installTemporaryRemovalOnSignals();

// Writes `size` bytes to `path` through an AtomicFile.
void writeFileAtomically(const std::string& path, const void* data, size_t size);

}  // namespace candela
