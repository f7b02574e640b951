#include "app/serve/serve.h"

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <thread>

#include "app/serve/access_token.h"
#include "app/serve/client_hub.h"
#include "app/serve/http_server.h"
#include "app/serve/serve_loop.h"

namespace candela {

namespace {

std::atomic<bool> stopRequested{false};
static_assert(std::atomic<bool>::is_always_lock_free, "the signal handler sets it");

extern "C" void requestStop(int) { stopRequested = true; }

// How long the render loop has to return after SIGINT or SIGTERM before the process ends without it.
constexpr std::chrono::milliseconds kStopGrace{600};
constexpr std::chrono::milliseconds kStopPoll{20};

std::string urlHost(const std::string& bind) {
  if (bind == "0.0.0.0") return "127.0.0.1";  // any address: this machine's own works from here
  if (bind == "::") return "[::1]";
  return bind.find(':') != std::string::npos ? "[" + bind + "]" : bind;
}

AccessToken chooseToken(const ServeOptions& options) {
  if (!options.noToken) return options.token.empty() ? AccessToken::random() : AccessToken(options.token);
  if (!options.token.empty()) throw std::runtime_error("--no-token and --token exclude each other");
  if (!isLoopbackAddress(options.bind))
    throw std::runtime_error("--no-token: only a loopback address (127.0.0.1, ::1) may be served without a token");
  return AccessToken();
}

// Ends the process once a stop was asked and the render loop has not returned within kStopGrace: a frame in
// flight (up to minutes for a large one) is abandoned rather than waited for. Nothing is lost that the stop would
// have kept, except the --screenshot, which needs the loop; the exit status says so.
class StopDeadline {
 public:
  explicit StopDeadline(bool wantsExitFiles)
      : thread_([this, wantsExitFiles] {
          while (!stopRequested && !loopReturned_) std::this_thread::sleep_for(kStopPoll);
          const auto deadline = std::chrono::steady_clock::now() + kStopGrace;
          while (!loopReturned_ && std::chrono::steady_clock::now() < deadline) std::this_thread::sleep_for(kStopPoll);
          if (loopReturned_) return;
          std::fprintf(stderr, "candela serve: stopped; the frame being rendered was abandoned%s\n",
                       wantsExitFiles ? ", so there is no --screenshot" : "");
          std::fflush(stderr);
          std::_Exit(wantsExitFiles ? 1 : 0);
        }) {}
  ~StopDeadline() {
    loopReturned_ = true;
    thread_.join();
  }
  StopDeadline(const StopDeadline&) = delete;
  StopDeadline& operator=(const StopDeadline&) = delete;

 private:
  std::atomic<bool> loopReturned_{false};
  std::thread thread_;  // last: it starts once the flag exists
};

}  // namespace

int runServe(ServeOptions options) {
  const AccessToken token = chooseToken(options);
  ClientHub hub;
  HttpServer server(options.bind, options.port, token, hub);  // binds first: a busy port is told at once
  ServeLoop loop(options.interactive, hub);
  server.start();
  std::signal(SIGINT, requestStop);
  std::signal(SIGTERM, requestStop);
  std::string url = "http://" + urlHost(options.bind) + ":" + std::to_string(server.port()) + "/";
  if (token.required()) url += "?token=" + token.value();
  std::printf("candela serve: open %s\n", url.c_str());
  std::fflush(stdout);
  {
    StopDeadline deadline(!options.interactive.screenshot.empty());
    loop.run(stopRequested);
  }
  server.stop();
  std::fprintf(stderr, "candela serve: stopped\n");
  loop.writeExitFiles();
  return 0;
}

}  // namespace candela
