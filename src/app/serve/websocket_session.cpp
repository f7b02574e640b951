#include "app/serve/websocket_session.h"

#include <boost/asio/post.hpp>
#include <boost/beast/core/buffers_to_string.hpp>

#include <algorithm>
#include <variant>

namespace candela {

namespace beast = boost::beast;
namespace websocket = beast::websocket;

WebSocketSession::WebSocketSession(boost::asio::ip::tcp::socket socket, ClientHub& hub)
    : ws_(std::move(socket)), hub_(hub) {
  // A frame is one message written at once: Nagle's algorithm would hold a small one (a video frame at rest) back
  // until the browser's delayed acknowledgement, tens of milliseconds.
  beast::error_code ignored;
  beast::get_lowest_layer(ws_).socket().set_option(boost::asio::ip::tcp::no_delay(true), ignored);
}

void WebSocketSession::run(beast::http::request<beast::http::empty_body> upgrade) {
  // Pings an idle browser and drops one that stops answering; a handshake must finish in 30 seconds.
  ws_.set_option(websocket::stream_base::timeout::suggested(beast::role_type::server));
  // A frame goes out as one WebSocket frame: fragments of the write buffer's 4 KB each would cost a 1080p JPEG a
  // hundred frame headers and writes.
  ws_.auto_fragment(false);
  ws_.read_message_max(kMaxMessageBytes);
  ws_.async_accept(upgrade, [self = shared_from_this()](beast::error_code error) { self->onAccept(error); });
}

void WebSocketSession::onAccept(beast::error_code error) {
  if (error) return;
  id_ = hub_.attach(shared_from_this());
  if (id_ == 0) {
    ws_.async_close(websocket::close_reason(websocket::close_code::try_again_later, "too many viewers"),
                    [self = shared_from_this()](beast::error_code) {});
    return;
  }
  read();
}

void WebSocketSession::read() {
  ws_.async_read(buffer_, [self = shared_from_this()](beast::error_code error, size_t) { self->onRead(error); });
}

// A token bucket: a browser that sends faster than kMessagesPerSecond for long has the excess dropped.
bool WebSocketSession::withinRate() {
  const auto now = std::chrono::steady_clock::now();
  tokens_ =
      std::min(kMessageBurst, tokens_ + kMessagesPerSecond * std::chrono::duration<double>(now - lastRefill_).count());
  lastRefill_ = now;
  if (tokens_ < 1.0) return false;
  tokens_ -= 1.0;
  return true;
}

void WebSocketSession::onRead(beast::error_code error) {
  if (error) {  // closed, timed out, or a message over kMaxMessageBytes
    if (error == websocket::error::message_too_big) hub_.dropped(id_, "a message over the size limit; closing");
    leave();
    return;
  }
  if (!ws_.got_text()) {
    hub_.dropped(id_, "a binary message");
  } else {
    const std::string text = beast::buffers_to_string(buffer_.data());
    std::string problem;
    std::optional<ClientMessage> message = parseClientMessage(text, problem);
    // A frame's acknowledgement is never dropped: without it the browser gets no frame for kAckTimeout. It comes
    // once per frame sent, on top of the input that may come as fast.
    if (message && std::holds_alternative<FrameAckMessage>(*message))
      hub_.receive(id_, std::move(*message));
    else if (!withinRate())
      hub_.dropped(id_, "messages faster than the rate limit");
    else if (message)
      hub_.receive(id_, std::move(*message));
    else
      hub_.dropped(id_, problem);
  }
  buffer_.consume(buffer_.size());
  read();
}

void WebSocketSession::leave() {
  if (id_ != 0) hub_.detach(id_);
  id_ = 0;
}

void WebSocketSession::sendMessage(std::shared_ptr<const std::string> message, bool binary) {
  boost::asio::post(ws_.get_executor(), [self = shared_from_this(), message = std::move(message), binary] {
    self->outgoing_.push(message, binary);
    self->pump();
  });
}

void WebSocketSession::sendFrame(std::shared_ptr<const std::string> frame) {
  boost::asio::post(ws_.get_executor(), [self = shared_from_this(), frame = std::move(frame)] {
    self->pendingFrame_ = frame;
    self->pump();
  });
}

// One write at a time (Beast allows no more): queued messages first, then the latest frame.
void WebSocketSession::pump() {
  if (writing_) return;
  bool binary = true;
  if (std::optional<OutgoingQueue::Message> message = outgoing_.pop()) {
    writing_ = std::move(message->bytes);
    binary = message->binary;
  } else if (pendingFrame_) {
    writing_ = std::move(pendingFrame_);
    pendingFrame_.reset();
  } else {
    return;
  }
  ws_.binary(binary);
  ws_.async_write(boost::asio::buffer(*writing_), [self = shared_from_this()](beast::error_code error, size_t) {
    self->writing_.reset();
    if (error) return;  // the read fails too, and leaves
    self->pump();
  });
}

}  // namespace candela
