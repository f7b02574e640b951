#include "io/load_diagnostics.h"

#include <algorithm>
#include <cstdint>

namespace candela {

namespace {

// The length of the valid UTF-8 sequence at the start of `s` and its code point; 0 when it is not valid
// (overlong forms, surrogates and values beyond U+10FFFF included).
size_t utf8Sequence(std::string_view s, uint32_t& codePoint) {
  const auto byte = [&](size_t i) { return uint8_t(s[i]); };
  const uint8_t lead = byte(0);
  size_t length = lead >= 0xF5 ? 0 : lead >= 0xF0 ? 4 : lead >= 0xE0 ? 3 : lead >= 0xC2 ? 2 : 0;
  if (length == 0 || s.size() < length) return 0;
  codePoint = lead & (0x7F >> length);
  for (size_t i = 1; i < length; ++i) {
    if ((byte(i) & 0xC0) != 0x80) return 0;
    codePoint = (codePoint << 6) | (byte(i) & 0x3F);
  }
  const uint32_t smallest[] = {0, 0, 0x80, 0x800, 0x10000};
  if (codePoint < smallest[length] || codePoint > 0x10FFFF || (codePoint >= 0xD800 && codePoint <= 0xDFFF)) return 0;
  return length;
}

// C1 controls (U+009B is a one-character escape sequence on some terminals) and the characters that reorder
// the text displayed around them.
bool isHiddenControl(uint32_t c) {
  return (c >= 0x80 && c <= 0x9F) || (c >= 0x202A && c <= 0x202E) || (c >= 0x2066 && c <= 0x2069) || c == 0x200E ||
         c == 0x200F || c == 0x061C;
}

void appendEscaped(std::string& out, uint8_t byte) {
  static const char kHex[] = "0123456789abcdef";
  out += "\\x";
  out += kHex[byte >> 4];
  out += kHex[byte & 15];
}

}  // namespace

std::string printableText(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (size_t i = 0; i < text.size();) {
    const uint8_t c = uint8_t(text[i]);
    if (c == '\n' || c == '\r') {
      out += ' ';
      ++i;
    } else if (c >= 0x20 && c < 0x7F) {
      out += char(c);
      ++i;
    } else if (c < 0x80) {
      appendEscaped(out, c);
      ++i;
    } else {
      uint32_t codePoint = 0;
      const size_t length = utf8Sequence(text.substr(i), codePoint);
      if (length > 0 && !isHiddenControl(codePoint)) {
        out.append(text.substr(i, length));
      } else {  // the whole sequence of a hidden control, or the one byte that starts no valid sequence
        for (size_t k = 0; k < std::max<size_t>(length, 1); ++k) appendEscaped(out, uint8_t(text[i + k]));
      }
      i += std::max<size_t>(length, 1);
    }
  }
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

void failLoad(const std::string& file, const std::string& what) { throw LoadError(printableText(file + ": " + what)); }

void failLoad(const std::string& file, size_t line, const std::string& what) {
  throw LoadError(printableText(file + ":" + std::to_string(line) + ": " + what));
}

}  // namespace candela
