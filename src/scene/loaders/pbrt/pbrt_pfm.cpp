#include "scene/loaders/pbrt/pbrt_pfm.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstring>
#include <sstream>

#include "io/file_bytes.h"
#include "io/images/area_downscaler.h"
#include "io/load_budget.h"
#include "io/load_diagnostics.h"

namespace candela {

Texture readPfm(const std::string& path, uint32_t maxSide, TextureExtent* fileExtent) {
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
  const bool bigEndian = scale > 0;
  if (fileExtent) *fileExtent = {uint32_t(width), uint32_t(height), channels * uint32_t(sizeof(float))};
  const auto [targetWidth, targetHeight] = sizeWithin(uint32_t(width), uint32_t(height), maxSide);
  chargeLoadMemory(uint64_t(targetWidth) * targetHeight * channels * sizeof(float), path,
                   "a PFM image decoded at " + std::to_string(targetWidth) + "x" + std::to_string(targetHeight) +
                       " pixels");
  // PFM stores the bottom row first: the rows are fed to the downscaler top first.
  AreaDownscaler<float> target(uint32_t(width), uint32_t(height), targetWidth, targetHeight, channels);
  const size_t rowFloats = size_t(width) * channels;
  std::vector<float> row(rowFloats);
  for (long y = height - 1; y >= 0; --y) {
    const uint8_t* at = bytes.data() + pos + 4 * rowFloats * size_t(y);
    for (size_t i = 0; i < rowFloats; ++i) {
      uint32_t word;
      std::memcpy(&word, at + 4 * i, 4);
      if (bigEndian == (std::endian::native == std::endian::little)) word = __builtin_bswap32(word);
      float v;
      std::memcpy(&v, &word, 4);
      row[i] = std::isfinite(v) ? v : 0.0f;
    }
    target.addRow(row.data());
  }
  Texture t;
  t.width = targetWidth;
  t.height = targetHeight;
  t.channels = channels;
  t.floats = target.finish();
  return t;
}

}  // namespace candela
