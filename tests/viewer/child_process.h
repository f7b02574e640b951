#pragma once
#include <sys/types.h>

#include <string>
#include <vector>

namespace candela::test {

// A program started by a test, its standard error captured in a file.
class ChildProcess {
 public:
  // Starts `argv` (argv[0] looked up in PATH); without `display`, DISPLAY is removed from its environment.
  ChildProcess(const std::vector<std::string>& argv, const std::string& stderrPath, bool display = true);
  ~ChildProcess();  // kills the child if it is still running
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  // The exit status, or -1 when it did not exit within `seconds` (it is then killed) or died from a signal.
  int wait(double seconds);
  bool running();
  std::string stderrText() const;

 private:
  pid_t pid_ = -1;
  std::string stderrPath_;
};

// Runs a command to completion; returns its exit status as ChildProcess::wait does.
int runCommand(const std::vector<std::string>& argv, double seconds, std::string* stderrText = nullptr);

}  // namespace candela::test
