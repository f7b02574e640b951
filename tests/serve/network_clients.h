#pragma once
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core/flat_buffer.hpp>
#include <boost/beast/websocket/stream.hpp>

#include <cstdint>
#include <string>

namespace candela::test {

// Plain clients of candela serve on 127.0.0.1, blocking, one per thread; errors throw boost::system::system_error.

struct HttpAnswer {
  unsigned status = 0;
  std::string contentType;
  std::string body;
};

// One GET on a connection of its own. `host` is the Host header (default: "127.0.0.1:<port>"); `source` the
// address the connection comes from (default: the system's choice, 127.0.0.1; any of 127.0.0.0/8 works).
HttpAnswer httpGet(uint16_t port, const std::string& target, const std::string& host = "",
                   const std::string& source = "");

// A connection from `source` that sends the start of a request and never its end, as a client that holds
// connections open does.
class HalfOpenRequest {
 public:
  HalfOpenRequest(uint16_t port, const std::string& source);
  // Whether the server has closed the connection (within `seconds`).
  bool closedByServer(double seconds);

 private:
  boost::asio::io_context io_;
  boost::asio::ip::tcp::socket socket_;
};

// Sends `bytes` as they are on a new connection and returns the status of the answer (0 for none).
unsigned rawRequestStatus(uint16_t port, const std::string& bytes);

// A browser's WebSocket ("/ws", with the page's Origin).
class WebSocketClient {
 public:
  // With `token` (the server's, or empty for a server without one) in the address, as the page sends it.
  WebSocketClient(uint16_t port, const std::string& token);

  struct Message {
    bool binary = false;
    std::string text;     // a text message, or a binary message's JSON header
    std::string payload;  // a binary message's bytes after the header
  };
  Message read();
  void send(const std::string& json);
  void close();  // a WebSocket close; returns once the server's close came (frames before it are dropped)
  void drop();   // the TCP connection closed without a word, as by a browser's crash

 private:
  boost::asio::io_context io_;
  boost::beast::websocket::stream<boost::asio::ip::tcp::socket> ws_;
  boost::beast::flat_buffer buffer_;
};

}  // namespace candela::test
