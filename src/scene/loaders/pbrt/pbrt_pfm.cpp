#include "scene/loaders/pbrt/pbrt_pfm.h"

#include <bit>
#include <cctype>
#include <cmath>
#include <cstring>
#include <sstream>

#include "io/file_bytes.h"
#include "io/load_diagnostics.h"

namespace candela {

Texture readPfm(const std::string& path) {
  std::vector<uint8_t> bytes = readFileBytes(path);
  // The header: "PF" or "Pf", width, height and a scale whose sign gives the byte order, each followed by
  // white space; the last by exactly one white-space character.
  size_t pos = 0;
  auto token = [&]() {
    while (pos < bytes.size() && std::isspace(bytes[pos])) ++pos;
    size_t start = pos;
    while (pos < bytes.size() && !std::isspace(bytes[pos]) && pos - start < 32) ++pos;
    return std::string(bytes.begin() + long(start), bytes.begin() + long(pos));
  };
  std::string magic = token(), w = token(), h = token(), s = token();
  if (pos >= bytes.size() || (magic != "PF" && magic != "Pf")) failLoad(path, "not a PFM image");
  ++pos;  // the single white-space character before the pixels
  char* end = nullptr;
  long width = std::strtol(w.c_str(), &end, 10);
  long height = std::strtol(h.c_str(), &end, 10);
  double scale = std::strtod(s.c_str(), &end);
  if (width <= 0 || height <= 0 || !std::isfinite(scale) || scale == 0.0) failLoad(path, "malformed PFM header");
  uint32_t channels = magic == "PF" ? 3 : 1;
  uint64_t floats = uint64_t(width) * uint64_t(height) * channels;
  if (width > (1 << 20) || height > (1 << 20) || floats * 4 > bytes.size() - pos)
    failLoad(path, "the PFM header claims more pixels than the file holds");
  bool bigEndian = scale > 0;
  Texture t;
  t.width = uint32_t(width);
  t.height = uint32_t(height);
  t.channels = channels;
  t.floats.resize(floats);
  for (uint64_t i = 0; i < floats; ++i) {
    uint32_t word;
    std::memcpy(&word, bytes.data() + pos + 4 * i, 4);
    if (bigEndian == (std::endian::native == std::endian::little)) word = __builtin_bswap32(word);
    float v;
    std::memcpy(&v, &word, 4);
    // PFM stores the bottom row first.
    uint64_t pixel = i / channels, row = pixel / uint64_t(width), column = pixel % uint64_t(width);
    t.floats[((uint64_t(height) - 1 - row) * uint64_t(width) + column) * channels + i % channels] =
        std::isfinite(v) ? v : 0.0f;
  }
  return t;
}

}  // namespace candela
