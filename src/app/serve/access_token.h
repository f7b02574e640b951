#pragma once
#include <string>
#include <string_view>

namespace candela {

// The secret a browser shows to use the server, as Jupyter does: in the address's query (?token=...) for the first
// request, then in a cookie the server sets.
class AccessToken {
 public:
  AccessToken() = default;  // no token: every request is allowed (loopback only)
  explicit AccessToken(std::string value) : value_(std::move(value)) {}
  static AccessToken random();  // 128 bits from the system's random device, as 32 hexadecimal digits

  bool required() const { return !value_.empty(); }
  const std::string& value() const { return value_; }
  // Whether a request with this target (path and query) and Cookie header may proceed.
  bool admits(std::string_view target, std::string_view cookieHeader) const;

  static constexpr std::string_view kCookieName = "candela_token";

 private:
  bool matches(std::string_view candidate) const;
  std::string value_;
};

// The value of `name` in a query string ("a=1&token=x") or a Cookie header ("a=1; token=x"); empty when absent.
std::string_view queryParameter(std::string_view target, std::string_view name);
std::string_view cookieValue(std::string_view cookieHeader, std::string_view name);

// Whether `address` is a loopback address (127.0.0.0/8, ::1, "localhost"); others need a token.
bool isLoopbackAddress(const std::string& address);

}  // namespace candela

namespace candela {

// Whether a WebSocket request's Origin header ("http://host:port") names the host the request was sent to (its
// Host header), so that a page from another site cannot open the stream in a visitor's browser. A request with
// no Origin (not from a browser) passes: it carries no visitor's cookie.
bool sameOrigin(std::string_view origin, std::string_view host);

// Whether a Host header ("127.0.0.1:8080", "localhost:8080", "[::1]:8080") names this machine by a loopback name.
// A server without a token answers only such requests: a site whose name an attacker points at 127.0.0.1 (DNS
// rebinding) sends its own name, and is refused.
bool isLoopbackHost(std::string_view host);

}  // namespace candela
