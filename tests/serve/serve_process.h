#pragma once
#include <sys/types.h>

#include <cstdint>
#include <string>
#include <vector>

namespace candela::test {

// `candela serve` started by a test, as tests/serve/serve_harness.mjs starts it: it reads the address the server
// prints on its standard output and keeps its standard error in a file. The server runs on one CPU, so that the
// CPU backend renders with one TBB thread: TBB is not instrumented, and under ThreadSanitizer its hand-over
// between threads would be reported as races.
class ServeProcess {
 public:
  // Starts `candela serve <arguments>`; throws std::runtime_error when it does not print its address within
  // `seconds`.
  ServeProcess(const std::string& candela, const std::vector<std::string>& arguments, double seconds);
  ~ServeProcess();  // kills the server if it still runs
  ServeProcess(const ServeProcess&) = delete;
  ServeProcess& operator=(const ServeProcess&) = delete;

  uint16_t port() const { return port_; }
  const std::string& url() const { return url_; }      // as printed: "http://127.0.0.1:PORT/?token=..."
  const std::string& token() const { return token_; }  // the token in it; empty with --no-token

  // Sends SIGTERM and waits up to `seconds`: the exit status, or -1 when it did not exit in time (it is then
  // killed) or died from a signal.
  int stop(double seconds);
  void signal(int number);  // sends it, nothing else
  // Waits up to `seconds` for the exit that a signal asked for: as stop().
  int wait(double seconds);
  // Ends it at once (SIGKILL); from any thread.
  void kill();
  std::string stderrText() const;

 private:
  pid_t pid_ = -1;
  int stdout_ = -1;
  std::string stderrPath_;
  std::string url_;
  std::string token_;
  uint16_t port_ = 0;
};

}  // namespace candela::test
