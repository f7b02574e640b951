#include "app/serve/http_server.h"

#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/strand.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket/rfc6455.hpp>

#include <list>
#include <map>
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

class HttpSession;

// The HTTP connections open now, by the address they come from, and those that have not yet shown the token (or,
// without a token, made a request addressed to a loopback name), oldest first. A connection over a limit takes
// the place of the oldest unproven one (of its address, else of any), so that connections that send nothing, or
// a header byte by byte, cannot keep anyone else out: they are the first to go. Only the network thread uses it.
class Connections {
 public:
  // Whether a connection from `address` may open; closes an unproven one to make room where needed.
  bool admit(const asio::ip::address& address);
  std::list<HttpSession*>::iterator opened(HttpSession* session);
  void proven(std::list<HttpSession*>::iterator& place);
  void closed(const asio::ip::address& address, std::list<HttpSession*>::iterator& place);

 private:
  bool evictOldest(const asio::ip::address* of);
  std::map<asio::ip::address, int> perAddress_;
  int total_ = 0;
  std::list<HttpSession*> unproven_;  // oldest first
};

// One HTTP connection: reads requests (headers only; bodies are refused) and answers each, until the browser
// closes it or upgrades it to the WebSocket. Its first request must come within kHeaderTimeout of the connection
// and carry the token; a request without it gets 403 and the connection is closed.
class HttpSession : public std::enable_shared_from_this<HttpSession> {
 public:
  HttpSession(tcp::socket socket, asio::ip::address address, const AccessToken& token, ClientHub& hub,
              Connections& connections)
      : address_(std::move(address)),
        stream_(std::move(socket)),
        token_(token),
        hub_(hub),
        connections_(connections),
        place_(connections.opened(this)) {}
  ~HttpSession() { release(); }

  const asio::ip::address& address() const { return address_; }

  void read() {
    parser_.emplace();
    parser_->header_limit(kMaxHeaderBytes);
    parser_->body_limit(0);
    stream_.expires_after(kHeaderTimeout);
    http::async_read(stream_, buffer_, *parser_,
                     [self = shared_from_this()](beast::error_code error, size_t) { self->onRead(error); });
  }

  // Makes room for another connection at once: it counts no more, and its pending read ends, and with it this
  // connection.
  void evict() {
    release();
    beast::error_code ignored;
    stream_.socket().close(ignored);
  }

 private:
  void onRead(beast::error_code error) {
    if (error) {
      if (error != http::error::end_of_stream && error != beast::error::timeout &&
          error != asio::error::operation_aborted && error != asio::error::bad_descriptor)
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
              false);
      return;
    }
    connections_.proven(place_);
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
    stream_.expires_after(kHeaderTimeout);  // a client that reads nothing cannot hold the connection either
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

  void release() {
    if (released_) return;
    released_ = true;
    connections_.closed(address_, place_);
  }

  asio::ip::address address_;
  beast::tcp_stream stream_;
  beast::flat_buffer buffer_;
  std::optional<http::request_parser<http::empty_body>> parser_;
  const AccessToken& token_;
  ClientHub& hub_;
  Connections& connections_;
  std::list<HttpSession*>::iterator place_;  // in the unproven connections; their end() once proven
  bool released_ = false;
};

bool Connections::evictOldest(const asio::ip::address* of) {
  for (HttpSession* session : unproven_)
    if (!of || session->address() == *of) {
      session->evict();
      return true;
    }
  return false;
}

bool Connections::admit(const asio::ip::address& address) {
  const auto it = perAddress_.find(address);
  if (it != perAddress_.end() && it->second >= kMaxHttpConnectionsPerAddress && !evictOldest(&address)) return false;
  return total_ < kMaxHttpConnections || evictOldest(nullptr);
}

std::list<HttpSession*>::iterator Connections::opened(HttpSession* session) {
  ++perAddress_[session->address()];
  ++total_;
  return unproven_.insert(unproven_.end(), session);
}

void Connections::proven(std::list<HttpSession*>::iterator& place) {
  if (place == unproven_.end()) return;
  unproven_.erase(place);
  place = unproven_.end();
}

void Connections::closed(const asio::ip::address& address, std::list<HttpSession*>::iterator& place) {
  proven(place);
  --total_;
  if (--perAddress_[address] == 0) perAddress_.erase(address);
}

}  // namespace

struct HttpServer::Impl {
  // Declared before the io_context: the connections its pending handlers hold refer to them when it destroys
  // them.
  AccessToken token;
  ClientHub& hub;
  Connections connections;
  asio::io_context io{1};
  tcp::acceptor acceptor{io};

  Impl(AccessToken t, ClientHub& h) : token(std::move(t)), hub(h) {}

  void accept() {
    acceptor.async_accept(asio::make_strand(io), [this](beast::error_code error, tcp::socket socket) {
      if (error == asio::error::operation_aborted) return;
      beast::error_code peerError;
      const tcp::endpoint peer = error ? tcp::endpoint() : socket.remote_endpoint(peerError);
      // A connection over the limits is closed at once (the socket's destructor); an evicted one goes once its
      // read has ended.
      if (!error && !peerError && connections.admit(peer.address()))
        std::make_shared<HttpSession>(std::move(socket), peer.address(), token, hub, connections)->read();
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
