#include "app/serve/access_token.h"

#include <array>
#include <cstdint>
#include <random>

namespace candela {

AccessToken AccessToken::random() {
  std::random_device device;
  static constexpr char kHex[] = "0123456789abcdef";
  std::string value;
  for (int i = 0; i < 4; ++i) {
    uint32_t word = device();
    for (int nibble = 0; nibble < 8; ++nibble, word >>= 4) value += kHex[word & 15u];
  }
  return AccessToken(value);
}

// Compares every byte whatever the first difference, so that the time taken does not tell how much matched.
bool AccessToken::matches(std::string_view candidate) const {
  if (candidate.size() != value_.size()) return false;
  unsigned char difference = 0;
  for (size_t i = 0; i < value_.size(); ++i) difference |= static_cast<unsigned char>(candidate[i] ^ value_[i]);
  return difference == 0;
}

bool AccessToken::admits(std::string_view target, std::string_view cookieHeader) const {
  if (!required()) return true;
  return matches(queryParameter(target, "token")) || matches(cookieValue(cookieHeader, kCookieName));
}

namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
  while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
  return s;
}

std::string_view findPair(std::string_view list, char separator, std::string_view name) {
  while (!list.empty()) {
    const size_t end = list.find(separator);
    const std::string_view pair = trim(list.substr(0, end));
    const size_t equals = pair.find('=');
    if (equals != std::string_view::npos && pair.substr(0, equals) == name) return pair.substr(equals + 1);
    if (end == std::string_view::npos) break;
    list.remove_prefix(end + 1);
  }
  return {};
}

}  // namespace

std::string_view queryParameter(std::string_view target, std::string_view name) {
  const size_t question = target.find('?');
  if (question == std::string_view::npos) return {};
  return findPair(target.substr(question + 1), '&', name);
}

std::string_view cookieValue(std::string_view cookieHeader, std::string_view name) {
  return findPair(cookieHeader, ';', name);
}

bool isLoopbackAddress(const std::string& address) {
  if (address == "localhost" || address == "::1") return true;
  // 127.a.b.c, four numbers, nothing after them: "127.0.0.1.example.com" is a name anyone may point anywhere.
  if (address.rfind("127.", 0) != 0) return false;
  int parts = 1, digits = 0;
  for (char c : address) {
    if (c == '.') {
      if (digits == 0) return false;
      ++parts;
      digits = 0;
    } else if (c >= '0' && c <= '9' && digits < 3) {
      ++digits;
    } else {
      return false;
    }
  }
  return parts == 4 && digits > 0;
}

}  // namespace candela

namespace candela {

bool sameOrigin(std::string_view origin, std::string_view host) {
  if (origin.empty()) return true;
  for (std::string_view scheme : {"http://", "https://"})
    if (origin.substr(0, scheme.size()) == scheme) return origin.substr(scheme.size()) == host;
  return false;
}

}  // namespace candela

namespace candela {

bool isLoopbackHost(std::string_view host) {
  std::string_view name = host;
  if (!name.empty() && name.front() == '[') {
    const size_t close = name.find(']');
    if (close == std::string_view::npos) return false;
    name = name.substr(1, close - 1);
  } else {
    name = name.substr(0, name.find(':'));
  }
  return isLoopbackAddress(std::string(name));
}

}  // namespace candela
