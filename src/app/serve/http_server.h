#pragma once
#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <thread>

#include "app/serve/access_token.h"
#include "app/serve/client_hub.h"

namespace candela {

// At most this many HTTP connections at once, and this many from one address (WebSockets are ClientHub's).
constexpr int kMaxHttpConnections = 64;
constexpr int kMaxHttpConnectionsPerAddress = 16;
// A request's header must arrive within this time (from the connection, or from the answer before it).
constexpr std::chrono::seconds kHeaderTimeout{5};

// The HTTP and WebSocket side of candela serve, on Boost.Beast, in one network thread of its own. It answers GET
// for the page's embedded files (web_assets.h) and nothing else, upgrades "/ws" to the WebSocket that carries
// frames and messages (websocket_session.h), and refuses every request without the token when one is required,
// closing the connection. A connection that has not shown the token is the first to be closed when another needs
// its place, so that clients that open connections and send nothing cannot keep others out.
class HttpServer {
 public:
  // Binds `address` and `port` (0: any free port); throws std::runtime_error with one sentence when it cannot.
  HttpServer(const std::string& address, uint16_t port, AccessToken token, ClientHub& hub);
  ~HttpServer();
  HttpServer(const HttpServer&) = delete;
  HttpServer& operator=(const HttpServer&) = delete;

  uint16_t port() const;
  void start();  // starts the network thread
  void stop();   // closes every connection and joins the thread

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
  std::thread thread_;
};

}  // namespace candela
