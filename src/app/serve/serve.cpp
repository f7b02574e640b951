#include "app/serve/serve.h"

#include <atomic>
#include <csignal>
#include <cstdio>
#include <stdexcept>

#include "app/serve/access_token.h"
#include "app/serve/client_hub.h"
#include "app/serve/http_server.h"
#include "app/serve/serve_loop.h"

namespace candela {

namespace {

std::atomic<bool> stopRequested{false};
static_assert(std::atomic<bool>::is_always_lock_free, "the signal handler sets it");

extern "C" void requestStop(int) { stopRequested = true; }

std::string urlHost(const std::string& bind) {
  if (bind == "0.0.0.0") return "127.0.0.1";  // any address: this machine's own works from here
  if (bind == "::") return "[::1]";
  return bind.find(':') != std::string::npos ? "[" + bind + "]" : bind;
}

}  // namespace

int runServe(ServeOptions options) {
  AccessToken token(options.token);
  if (!token.required() && !isLoopbackAddress(options.bind)) token = AccessToken::random();
  ClientHub hub(options.offerVideo);
  HttpServer server(options.bind, options.port, token, hub);  // binds first: a busy port is told at once
  ServeLoop loop(options.interactive, hub);
  server.start();
  std::signal(SIGINT, requestStop);
  std::signal(SIGTERM, requestStop);
  std::string url = "http://" + urlHost(options.bind) + ":" + std::to_string(server.port()) + "/";
  if (token.required()) url += "?token=" + token.value();
  std::printf("candela serve: open %s\n", url.c_str());
  std::fflush(stdout);
  loop.run(stopRequested);
  server.stop();
  std::fprintf(stderr, "candela serve: stopped\n");
  loop.writeExitFiles();
  return 0;
}

}  // namespace candela
