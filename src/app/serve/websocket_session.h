#pragma once
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core/flat_buffer.hpp>
#include <boost/beast/core/tcp_stream.hpp>
#include <boost/beast/http/empty_body.hpp>
#include <boost/beast/http/message.hpp>
#include <boost/beast/websocket/stream.hpp>

#include <chrono>
#include <memory>
#include <string>

#include "app/serve/client_hub.h"
#include "app/serve/outgoing_queue.h"

namespace candela {

// One browser's WebSocket. Reads text messages, checks their size, rate and content and hands the valid ones to
// the hub; writes queued messages first (bounded in bytes: outgoing_queue.h), then the latest frame. Lives on the
// network thread: sendMessage and sendFrame post their work there.
class WebSocketSession : public ClientConnection, public std::enable_shared_from_this<WebSocketSession> {
 public:
  static constexpr size_t kMaxMessageBytes = 16 * 1024;
  static constexpr double kMessagesPerSecond = 200.0;  // sustained; bursts up to kMessageBurst
  static constexpr double kMessageBurst = 400.0;

  WebSocketSession(boost::asio::ip::tcp::socket socket, ClientHub& hub);
  void run(boost::beast::http::request<boost::beast::http::empty_body> upgrade);

  void sendMessage(std::shared_ptr<const std::string> message, bool binary) override;
  void sendFrame(std::shared_ptr<const std::string> frame) override;

 private:
  void onAccept(boost::beast::error_code error);
  void read();
  void onRead(boost::beast::error_code error);
  bool withinRate();
  void pump();
  void leave();

  boost::beast::websocket::stream<boost::beast::tcp_stream> ws_;
  ClientHub& hub_;
  uint64_t id_ = 0;
  boost::beast::flat_buffer buffer_;
  OutgoingQueue outgoing_;
  std::shared_ptr<const std::string> pendingFrame_;
  std::shared_ptr<const std::string> writing_;
  double tokens_ = kMessageBurst;
  std::chrono::steady_clock::time_point lastRefill_ = std::chrono::steady_clock::now();
};

}  // namespace candela
