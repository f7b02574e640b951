#include "app/serve/serve.h"

#include <pthread.h>
#include <signal.h>

#include <atomic>
#include <chrono>
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

// How long the render loop has to return after SIGINT or SIGTERM before the process ends without it.
constexpr std::chrono::milliseconds kStopGrace{500};
constexpr std::chrono::milliseconds kStopPoll{10};

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

// SIGINT and SIGTERM, taken by a thread of their own: blocked in every thread made after this object (the network
// thread, the backend's), so that the render loop's thread need not reach a point where it can run a handler
// (under ThreadSanitizer, a call it intercepts) for the stop to be seen. Once a stop is asked, the render loop
// has kStopGrace to return; after that the process ends without it: a frame in flight (minutes for a large one)
// is abandoned rather than waited for. Nothing is lost that the stop would have kept, except the --screenshot,
// which needs the loop; the exit status says so.
class StopRequests {
 public:
  explicit StopRequests(bool wantsExitFiles) {
    sigemptyset(&signals_);
    sigaddset(&signals_, SIGINT);
    sigaddset(&signals_, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &signals_, nullptr);
    thread_ = std::thread([this, wantsExitFiles] {
      int signal = 0;
      sigwait(&signals_, &signal);
      if (loopReturned_) return;  // woken by the destructor
      stopRequested_ = true;
      const auto deadline = std::chrono::steady_clock::now() + kStopGrace;
      while (!loopReturned_ && std::chrono::steady_clock::now() < deadline) std::this_thread::sleep_for(kStopPoll);
      if (loopReturned_) return;
      std::fprintf(stderr, "candela serve: stopped; the frame being rendered was abandoned%s\n",
                   wantsExitFiles ? ", so there is no --screenshot" : "");
      std::fflush(stderr);
      std::_Exit(wantsExitFiles ? 1 : 0);
    });
  }
  // Call once the render loop has returned.
  void loopReturned() {
    loopReturned_ = true;
    if (!stopRequested_) pthread_kill(thread_.native_handle(), SIGTERM);  // ends its wait
    thread_.join();
  }
  ~StopRequests() {
    if (thread_.joinable()) loopReturned();
  }
  StopRequests(const StopRequests&) = delete;
  StopRequests& operator=(const StopRequests&) = delete;

  const std::atomic<bool>& stopRequested() const { return stopRequested_; }

 private:
  sigset_t signals_;
  std::atomic<bool> stopRequested_{false}, loopReturned_{false};
  std::thread thread_;
};

}  // namespace

int runServe(ServeOptions options) {
  const AccessToken token = chooseToken(options);
  StopRequests stop(!options.interactive.screenshot.empty());  // before any other thread starts
  ClientHub hub(options.offerVideo);
  HttpServer server(options.bind, options.port, token, hub);  // binds first: a busy port is told at once
  ServeLoop loop(options.interactive, hub);
  server.start();
  std::string url = "http://" + urlHost(options.bind) + ":" + std::to_string(server.port()) + "/";
  if (token.required()) url += "?token=" + token.value();
  std::printf("candela serve: open %s\n", url.c_str());
  std::fflush(stdout);
  loop.run(stop.stopRequested());
  stop.loopReturned();
  server.stop();
  std::fprintf(stderr, "candela serve: stopped\n");
  loop.writeExitFiles();
  return 0;
}

}  // namespace candela
