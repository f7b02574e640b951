#include "network_clients.h"

#include <poll.h>
#include <sys/socket.h>

#include <boost/asio/connect.hpp>
#include <boost/asio/write.hpp>
#include <boost/beast/core/buffers_to_string.hpp>
#include <boost/beast/http.hpp>

#include <algorithm>

namespace candela::test {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;

namespace {

tcp::endpoint server(uint16_t port) { return {asio::ip::make_address("127.0.0.1"), port}; }
std::string localHost(uint16_t port) { return "127.0.0.1:" + std::to_string(port); }

}  // namespace

HttpAnswer httpGet(uint16_t port, const std::string& target, const std::string& host, const std::string& source) {
  asio::io_context io;
  tcp::socket socket(io);
  if (!source.empty()) {
    socket.open(tcp::v4());
    socket.bind({asio::ip::make_address(source), 0});
  }
  socket.connect(server(port));
  http::request<http::empty_body> request(http::verb::get, target, 11);
  request.set(http::field::host, host.empty() ? localHost(port) : host);
  request.keep_alive(false);
  http::write(socket, request);
  beast::flat_buffer buffer;
  http::response<http::string_body> response;
  http::read(socket, buffer, response);
  return {response.result_int(), std::string(response[http::field::content_type]), response.body()};
}

unsigned rawRequestStatus(uint16_t port, const std::string& bytes) {
  asio::io_context io;
  tcp::socket socket(io);
  socket.connect(server(port));
  asio::write(socket, asio::buffer(bytes));
  beast::flat_buffer buffer;
  http::response<http::string_body> response;
  beast::error_code error;
  http::read(socket, buffer, response, error);
  return error ? 0 : response.result_int();
}

HalfOpenRequest::HalfOpenRequest(uint16_t port, const std::string& source) : socket_(io_) {
  socket_.open(tcp::v4());
  socket_.bind({asio::ip::make_address(source), 0});
  socket_.connect(server(port));
  asio::write(socket_, asio::buffer("GET / HTTP/1.1\r\nHost: " + localHost(port) + "\r\n"));
}

bool HalfOpenRequest::closedByServer(double seconds) {
  pollfd ready{socket_.native_handle(), POLLIN, 0};
  if (poll(&ready, 1, int(seconds * 1000)) <= 0) return false;
  char byte;
  return recv(socket_.native_handle(), &byte, 1, MSG_DONTWAIT) <= 0;  // the end, or a reset
}

WebSocketClient::WebSocketClient(uint16_t port, const std::string& token) : ws_(io_) {
  ws_.next_layer().connect(server(port));
  ws_.set_option(websocket::stream_base::decorator(
      [port](websocket::request_type& request) { request.set(http::field::origin, "http://" + localHost(port)); }));
  ws_.handshake(localHost(port), token.empty() ? "/ws" : "/ws?token=" + token);
}

WebSocketClient::Message WebSocketClient::read() {
  buffer_.consume(buffer_.size());
  ws_.read(buffer_);
  Message message;
  message.binary = ws_.got_binary();
  const std::string bytes = beast::buffers_to_string(buffer_.data());
  if (!message.binary) {
    message.text = bytes;
    return message;
  }
  // A binary message: the header's length (4 bytes, little-endian), the JSON header, the payload.
  uint32_t length = 0;
  for (size_t i = 0; i < 4 && i < bytes.size(); ++i) length |= uint32_t(uint8_t(bytes[i])) << (8 * i);
  message.text = bytes.substr(4, length);
  message.payload = bytes.substr(std::min(bytes.size(), size_t(4) + length));
  return message;
}

void WebSocketClient::send(const std::string& json) {
  ws_.text(true);
  ws_.write(asio::buffer(json));
}

void WebSocketClient::close() { ws_.close(websocket::close_code::normal); }

void WebSocketClient::drop() {
  beast::error_code ignored;
  ws_.next_layer().close(ignored);
}

}  // namespace candela::test
