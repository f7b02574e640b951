#include "app/serve/http_server.h"

#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/strand.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket/rfc6455.hpp>

#include <atomic>
#include <stdexcept>

#include "app/serve/web_assets.h"
#include "app/serve/websocket_session.h"

namespace candela {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
using tcp = asio::ip::tcp;

namespace {

std::string_view text(beast::string_view s) { return {s.data(), s.size()}; }

constexpr size_t kMaxHeaderBytes = 8 * 1024;
constexpr std::chrono::seconds kRequestTimeout{15};
constexpr int kMaxConnections = 64;

// One HTTP connection: reads requests (headers only; bodies are refused) and answers each, until the browser
// closes it or upgrades it to the WebSocket.
class HttpSession : public std::enable_shared_from_this<HttpSession> {
 public:
  HttpSession(tcp::socket socket, const AccessToken& token, ClientHub& hub, std::atomic<int>& connections)
      : stream_(std::move(socket)), token_(token), hub_(hub), connections_(connections) {
    ++connections_;
  }
  ~HttpSession() { --connections_; }

  void read() {
    parser_.emplace();
    parser_->header_limit(kMaxHeaderBytes);
    parser_->body_limit(0);
    stream_.expires_after(kRequestTimeout);
    http::async_read(stream_, buffer_, *parser_,
                     [self = shared_from_this()](beast::error_code error, size_t) { self->onRead(error); });
  }

 private:
  void onRead(beast::error_code error) {
    if (error) {
      if (error != http::error::end_of_stream && error != beast::error::timeout)
        respond(http::status::bad_request, "text/plain", "bad request\n", false);
      else
        close();
      return;
    }
    http::request<http::empty_body> request = parser_->release();
    const std::string target(request.target());
    if (!token_.required() && !isLoopbackHost(text(request[http::field::host]))) {
      respond(http::status::forbidden, "text/plain",
              "forbidden: without a token this server answers only requests addressed to localhost or 127.0.0.1\n",
              false);
      return;
    }
    if (!token_.admits(target, text(request[http::field::cookie]))) {
      respond(http::status::forbidden, "text/plain",
              "forbidden: this server needs its token; open the address candela serve printed (it ends in "
              "?token=...)\n",
              request.keep_alive());
      return;
    }
    if (beast::websocket::is_upgrade(request)) {
      if (target.substr(0, target.find('?')) != "/ws") {
        respond(http::status::not_found, "text/plain", "not found\n", false);
      } else if (!sameOrigin(text(request[http::field::origin]), text(request[http::field::host]))) {
        respond(http::status::forbidden, "text/plain", "forbidden: the page comes from another site\n", false);
      } else {
        stream_.expires_never();
        std::make_shared<WebSocketSession>(stream_.release_socket(), hub_)->run(std::move(request));
      }
      return;
    }
    if (request.method() != http::verb::get && request.method() != http::verb::head) {
      respond(http::status::method_not_allowed, "text/plain", "method not allowed\n", request.keep_alive());
      return;
    }
    const WebAsset* asset = findWebAsset(target);
    if (!asset) {
      respond(http::status::not_found, "text/plain", "not found\n", request.keep_alive());
      return;
    }
    // A token given in the address becomes a cookie, so that the page's own files and its WebSocket carry it.
    std::string cookie;
    if (token_.required() && !queryParameter(target, "token").empty())
      cookie = std::string(AccessToken::kCookieName) + "=" + token_.value() + "; Path=/; HttpOnly; SameSite=Strict";
    respond(http::status::ok, asset->contentType, request.method() == http::verb::head ? "" : asset->body,
            request.keep_alive(), cookie);
  }

  void respond(http::status status, std::string_view type, std::string_view body, bool keepAlive,
               const std::string& cookie = {}) {
    auto response = std::make_shared<http::response<http::string_body>>(status, 11);
    response->set(http::field::server, "candela");
    response->set(http::field::content_type, beast::string_view(type.data(), type.size()));
    response->set(http::field::cache_control, "no-store");
    response->set("X-Content-Type-Options", "nosniff");
    response->set("Content-Security-Policy",
                  "default-src 'self'; img-src 'self' blob: data:; connect-src 'self' ws: wss:");
    if (!cookie.empty()) response->set(http::field::set_cookie, cookie);
    response->body() = std::string(body);
    response->keep_alive(keepAlive);
    response->prepare_payload();
    http::async_write(stream_, *response, [self = shared_from_this(), response](beast::error_code error, size_t) {
      if (error || !response->keep_alive())
        self->close();
      else
        self->read();
    });
  }

  void close() {
    beast::error_code ignored;
    stream_.socket().shutdown(tcp::socket::shutdown_send, ignored);
  }

  beast::tcp_stream stream_;
  beast::flat_buffer buffer_;
  std::optional<http::request_parser<http::empty_body>> parser_;
  const AccessToken& token_;
  ClientHub& hub_;
  std::atomic<int>& connections_;
};

}  // namespace

struct HttpServer::Impl {
  // Declared before the io_context: the connections its pending handlers hold refer to them when it destroys
  // them.
  AccessToken token;
  ClientHub& hub;
  std::atomic<int> connections{0};
  asio::io_context io{1};
  tcp::acceptor acceptor{io};

  Impl(AccessToken t, ClientHub& h) : token(std::move(t)), hub(h) {}

  void accept() {
    acceptor.async_accept(asio::make_strand(io), [this](beast::error_code error, tcp::socket socket) {
      if (error == asio::error::operation_aborted) return;
      if (!error && connections < kMaxConnections)
        std::make_shared<HttpSession>(std::move(socket), token, hub, connections)->read();
      accept();
    });
  }
};

HttpServer::HttpServer(const std::string& address, uint16_t port, AccessToken token, ClientHub& hub)
    : impl_(std::make_unique<Impl>(std::move(token), hub)) {
  beast::error_code error;
  const asio::ip::address ip = asio::ip::make_address(address == "localhost" ? "127.0.0.1" : address, error);
  if (error) throw std::runtime_error("cannot serve on '" + address + "': not an IP address");
  const tcp::endpoint endpoint(ip, port);
  impl_->acceptor.open(endpoint.protocol(), error);
  if (!error) impl_->acceptor.set_option(asio::socket_base::reuse_address(true), error);
  if (!error) impl_->acceptor.bind(endpoint, error);
  if (!error) impl_->acceptor.listen(asio::socket_base::max_listen_connections, error);
  if (error)
    throw std::runtime_error("cannot serve on " + address + " port " + std::to_string(port) + ": " + error.message());
}

HttpServer::~HttpServer() { stop(); }

uint16_t HttpServer::port() const { return impl_->acceptor.local_endpoint().port(); }

void HttpServer::start() {
  impl_->accept();
  thread_ = std::thread([this] { impl_->io.run(); });
}

void HttpServer::stop() {
  if (!thread_.joinable()) return;
  impl_->io.stop();
  thread_.join();
  impl_->hub.detachAll();  // before the io_context that the connections' sockets belong to goes
}

}  // namespace candela
