#include "serve_process.h"

#include <fcntl.h>
#include <poll.h>
#include <sched.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace candela::test {

namespace {

using Clock = std::chrono::steady_clock;

// The lowest CPU this process may run on, alone.
cpu_set_t oneCpu() {
  cpu_set_t allowed, one;
  CPU_ZERO(&one);
  if (sched_getaffinity(0, sizeof allowed, &allowed) != 0) throw std::runtime_error("cannot read the CPU affinity");
  for (int cpu = 0; cpu < CPU_SETSIZE; ++cpu)
    if (CPU_ISSET(cpu, &allowed)) {
      CPU_SET(cpu, &one);
      return one;
    }
  throw std::runtime_error("no CPU in the affinity mask");
}

// The exit status of `pid` once it exits within `seconds`, else -1 after killing it; -1 too for a death by signal.
int waitFor(pid_t pid, double seconds) {
  const auto deadline = Clock::now() + std::chrono::duration<double>(seconds);
  int status = 0;
  while (waitpid(pid, &status, WNOHANG) != pid) {
    if (Clock::now() > deadline) {
      ::kill(pid, SIGKILL);
      waitpid(pid, nullptr, 0);
      return -1;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

ServeProcess::ServeProcess(const std::string& candela, const std::vector<std::string>& arguments, double seconds) {
  char path[] = "/tmp/candela-serve-stderr-XXXXXX";
  const int stderrFd = mkstemp(path);
  if (stderrFd < 0) throw std::runtime_error("cannot create a file for the server's standard error");
  stderrPath_ = path;
  int out[2];
  if (pipe2(out, O_CLOEXEC) != 0) {
    ::close(stderrFd);
    throw std::runtime_error("cannot create a pipe");
  }
  std::vector<std::string> argv = {candela, "serve"};
  argv.insert(argv.end(), arguments.begin(), arguments.end());
  std::vector<char*> args;
  for (std::string& a : argv) args.push_back(a.data());
  args.push_back(nullptr);
  const cpu_set_t cpu = oneCpu();

  pid_ = fork();
  if (pid_ == 0) {  // only async-signal-safe calls from here to exec
    dup2(out[1], STDOUT_FILENO);
    dup2(stderrFd, STDERR_FILENO);
    sched_setaffinity(0, sizeof cpu, &cpu);
    execv(args[0], args.data());
    _exit(127);
  }
  ::close(out[1]);
  ::close(stderrFd);
  stdout_ = out[0];
  if (pid_ < 0) throw std::runtime_error(std::string("cannot start candela: ") + std::strerror(errno));

  const auto fail = [&](const std::string& why) {
    const std::string text = stderrText();
    ::kill(pid_, SIGKILL);
    waitpid(pid_, nullptr, 0);
    pid_ = -1;
    ::close(stdout_);
    unlink(stderrPath_.c_str());
    throw std::runtime_error(why + "; its standard error:\n" + text);
  };
  const auto deadline = Clock::now() + std::chrono::duration<double>(seconds);
  std::string printed;
  for (;;) {
    const size_t open = printed.find("open http://");
    if (open != std::string::npos && printed.find('\n', open) != std::string::npos) {
      const size_t start = open + 5, end = printed.find_first_of(" \n", start);
      url_ = printed.substr(start, end - start);
      const size_t colon = url_.rfind(':'), slash = url_.find('/', colon);
      port_ = uint16_t(std::stoul(url_.substr(colon + 1, slash - colon - 1)));
      if (const size_t token = url_.find("?token="); token != std::string::npos) token_ = url_.substr(token + 7);
      return;
    }
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (left <= 0) fail("candela serve printed no address within " + std::to_string(seconds) + " s");
    pollfd ready{stdout_, POLLIN, 0};
    if (poll(&ready, 1, int(left)) <= 0) continue;
    char buffer[512];
    const ssize_t n = read(stdout_, buffer, sizeof buffer);
    if (n <= 0) fail("candela serve exited before printing an address");
    printed.append(buffer, size_t(n));
  }
}

ServeProcess::~ServeProcess() {
  if (pid_ > 0) {
    ::kill(pid_, SIGKILL);
    waitpid(pid_, nullptr, 0);
  }
  if (stdout_ >= 0) ::close(stdout_);
  unlink(stderrPath_.c_str());
}

int ServeProcess::stop(double seconds) {
  if (pid_ <= 0) return -1;
  ::kill(pid_, SIGTERM);
  const int status = waitFor(pid_, seconds);
  pid_ = -1;
  return status;
}

void ServeProcess::signal(int number) {
  if (pid_ > 0) ::kill(pid_, number);
}

int ServeProcess::wait(double seconds) {
  if (pid_ <= 0) return -1;
  const int status = waitFor(pid_, seconds);
  pid_ = -1;
  return status;
}

void ServeProcess::kill() {
  if (pid_ > 0) ::kill(pid_, SIGKILL);
}

std::string ServeProcess::stderrText() const {
  std::ifstream in(stderrPath_);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace candela::test
