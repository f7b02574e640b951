#include "io/images/exr_decoding.h"

#include <OpenEXR/ImfArray.h>
#include <OpenEXR/ImfRgbaFile.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "io/images/area_downscaler.h"
#include "io/images/exr_memory_stream.h"
#include "io/images/image_decoding.h"
#include "io/load_budget.h"
#include "io/load_diagnostics.h"

namespace candela {

namespace {

// Pixels read at a time: the rows of an image are read in bands of about this many.
constexpr int64_t kBandPixels = int64_t(1) << 20;

// The size checks of a data window, on the header before any allocation.
void checkExrSize(const std::string& name, int64_t width, int64_t height, size_t fileSize, uint64_t maxPixels) {
  if (width <= 0 || height <= 0 || width > INT32_MAX || height > INT32_MAX)
    failLoad(name, "OpenEXR data window has no pixels");
  if (uint64_t(width) * uint64_t(height) > maxPixels)
    failLoad(name, "OpenEXR image of " + std::to_string(width) + "x" + std::to_string(height) +
                       " pixels is larger than the limit of " + std::to_string(maxPixels) + " pixels");
  checkImageHeader(name, uint64_t(width), uint64_t(height), fileSize);
  checkDecodedSize(name, uint64_t(width), uint64_t(height), sizeof(Imf::Rgba) + 3 * sizeof(float));
}

// The number of bytes OpenEXR reads for a value of `type` whatever the size an attribute declares, or
// kFollowsDeclaredSize for the types whose reader follows the declared size (strings, vectors, unknown types).
constexpr int64_t kFollowsDeclaredSize = -1;
constexpr int64_t kBeyondTheFile = -2;  // the value as OpenEXR reads it would run past the end of the file
int64_t fixedExrValueSize(const std::string& type) {
  static const std::pair<const char*, int64_t> sizes[] = {{"box2i", 16},
                                                          {"box2f", 16},
                                                          {"compression", 1},
                                                          {"lineOrder", 1},
                                                          {"envmap", 1},
                                                          {"deepImageState", 1},
                                                          {"float", 4},
                                                          {"int", 4},
                                                          {"double", 8},
                                                          {"v2i", 8},
                                                          {"v2f", 8},
                                                          {"v3i", 12},
                                                          {"v3f", 12},
                                                          {"m33f", 36},
                                                          {"m44f", 64},
                                                          {"tiledesc", 9},
                                                          {"chromaticities", 32},
                                                          {"rational", 8},
                                                          {"keycode", 28},
                                                          {"timecode", 8},
                                                          {"v2d", 16},
                                                          {"v3d", 24},
                                                          {"m33d", 72},
                                                          {"m44d", 128},
                                                          {"box2d", 32}};
  for (const auto& [name, bytes] : sizes)
    if (type == name) return bytes;
  return kFollowsDeclaredSize;
}

// The bytes OpenEXR reads for a channel list starting at `at`: (name\0, 16 bytes) per channel, up to an empty name.
int64_t channelListSize(const uint8_t* data, size_t at, size_t end) {
  const size_t start = at;
  while (at < end && data[at] != 0) {
    const void* nul = std::memchr(data + at, 0, end - at);
    if (!nul) return kBeyondTheFile;
    at = size_t(static_cast<const uint8_t*>(nul) - data) + 1 + 16;
  }
  return at < end ? int64_t(at + 1 - start) : kBeyondTheFile;
}

// The bytes OpenEXR reads (and allocates) for a preview image: its width and height, then 4 bytes per pixel.
int64_t previewSize(const uint8_t* data, size_t at, size_t end) {
  if (end - at < 8) return kBeyondTheFile;
  uint32_t wh[2];
  std::memcpy(wh, data + at, sizeof wh);
  const uint64_t pixels = uint64_t(wh[0]) * wh[1];  // below 2^64; 4 bytes each may not be
  return pixels > (end - at) / 4 ? kBeyondTheFile : 8 + 4 * int64_t(pixels);
}

}  // namespace

// Reads an OpenEXR file's headers as they lie in memory (magic number, version, then per part attributes of
// `name\0type\0size value` up to an empty name) and fails unless every attribute's value lies within the file,
// is read by OpenEXR as the size it declares (OpenEXR reads some types by their content, so a file could
// otherwise hide attributes from this check), and every data window is within the limits. OpenEXR allocates
// what an attribute of an unknown type claims before reading it: in the sanitizer build, 32 bytes claiming
// 2 GB took hundreds of MB and two seconds; under a memory limit, such a file ends in bad_alloc.
void checkExrHeaders(const std::string& name, const uint8_t* data, size_t size, uint64_t maxPixels,
                     bool checkDataWindows) {
  auto fail = [&](const std::string& why) { failLoad(name, "OpenEXR header " + why); };
  if (size < 8 || data[0] != 0x76 || data[1] != 0x2f || data[2] != 0x31 || data[3] != 0x01)
    failLoad(name, "not an OpenEXR image (no OpenEXR magic number)");
  const bool multiPart = (data[5] & 0x10) != 0;  // version flags, bit 12
  size_t at = 8;
  auto text = [&]() {
    const uint8_t* end = at < size ? static_cast<const uint8_t*>(std::memchr(data + at, 0, size - at)) : nullptr;
    if (!end) fail("is truncated");
    std::string s(reinterpret_cast<const char*>(data + at), size_t(end - (data + at)));
    at = size_t(end - data) + 1;
    return s;
  };
  for (bool firstPart = true;; firstPart = false) {
    if (at >= size) fail("is truncated");
    if (!firstPart && data[at] == 0) break;  // the empty header that ends a multi-part file's headers
    for (;;) {
      const std::string attribute = text();
      if (attribute.empty()) break;
      const std::string type = text();
      if (size - at < 4) fail("is truncated");
      int32_t bytes = 0;
      std::memcpy(&bytes, data + at, 4);
      at += 4;
      if (bytes < 0 || size_t(bytes) > size - at)
        fail("attribute '" + printableText(attribute) + "' claims " + std::to_string(bytes) +
             " bytes, more than the file holds");
      const int64_t read = type == "chlist"    ? channelListSize(data, at, size)
                           : type == "preview" ? previewSize(data, at, size)
                                               : fixedExrValueSize(type);
      if (read == kBeyondTheFile) fail("attribute '" + printableText(attribute) + "' runs past the end of the file");
      if (read != kFollowsDeclaredSize && read != bytes)
        fail("attribute '" + printableText(attribute) + "' declares " + std::to_string(bytes) +
             " bytes for a value of " + std::to_string(read));
      if (checkDataWindows && attribute == "dataWindow" && type == "box2i" && bytes == 16) {
        int32_t box[4];
        std::memcpy(box, data + at, sizeof box);
        checkExrSize(name, int64_t(box[2]) - box[0] + 1, int64_t(box[3]) - box[1] + 1, size, maxPixels);
      }
      at += size_t(bytes);
    }
    if (!multiPart) break;
  }
}

Texture decodeExr(const std::string& name, const uint8_t* data, size_t size, uint64_t maxPixels, uint32_t maxSide,
                  std::pair<uint32_t, uint32_t>* fileSize) {
  Texture t;
  t.name = name;
  t.channels = 3;
  checkExrHeaders(name, data, size, maxPixels);
  try {
    ExrMemoryStream stream(name, data, size);
    Imf::RgbaInputFile file(stream);
    const Imath::Box2i window = file.dataWindow();
    // The window may lie anywhere in int's range: its size and offsets are computed in 64 bits.
    const int64_t width = int64_t(window.max.x) - window.min.x + 1;
    const int64_t height = int64_t(window.max.y) - window.min.y + 1;
    checkExrSize(name, width, height, size, maxPixels);
    if (fileSize) *fileSize = {uint32_t(width), uint32_t(height)};
    const auto [targetWidth, targetHeight] = sizeWithin(uint32_t(width), uint32_t(height), maxSide);
    const int64_t bandRows = std::clamp<int64_t>(kBandPixels / width, 1, height);
    chargeLoadMemory(uint64_t(targetWidth) * targetHeight * 3 * sizeof(float), name,
                     "an OpenEXR image decoded at " + std::to_string(targetWidth) + "x" + std::to_string(targetHeight) +
                         " pixels");
    const uint64_t bandBytes = uint64_t(bandRows) * uint64_t(width) * (sizeof(Imf::Rgba) + 3 * sizeof(float));
    chargeLoadMemory(bandBytes, name, "a band of its rows");
    AreaDownscaler<float> target(uint32_t(width), uint32_t(height), targetWidth, targetHeight, 3);
    Imf::Array2D<Imf::Rgba> band(bandRows, width);
    std::vector<float> row(size_t(width) * 3);
    for (int64_t first = 0; first < height; first += bandRows) {
      const int64_t rows = std::min(bandRows, height - first);
      // OpenEXR addresses pixel (x, y) at base + x + y * width; base itself lies outside the band unless the band
      // starts at the window's origin, so it is computed as an address, not by pointer arithmetic.
      const int64_t originOffset = int64_t(window.min.x) + (int64_t(window.min.y) + first) * width;
      const uintptr_t base = reinterpret_cast<uintptr_t>(&band[0][0]) - uintptr_t(originOffset) * sizeof(Imf::Rgba);
      file.setFrameBuffer(reinterpret_cast<Imf::Rgba*>(base), 1, size_t(width));
      file.readPixels(int(window.min.y + first), int(window.min.y + first + rows - 1));
      for (int64_t y = 0; y < rows; ++y) {
        for (int64_t x = 0; x < width; ++x) {
          const Imf::Rgba& p = band[y][x];
          float* out = &row[size_t(x) * 3];
          for (int c = 0; c < 3; ++c) {
            const float v = c == 0 ? float(p.r) : c == 1 ? float(p.g) : float(p.b);
            out[c] = std::isfinite(v) && v > 0.0f ? v : 0.0f;
          }
        }
        target.addRow(row.data());
      }
    }
    releaseLoadMemory(bandBytes);
    t.width = targetWidth;
    t.height = targetHeight;
    t.floats = target.finish();
  } catch (const LoadError&) {
    throw;
  } catch (const std::exception& e) {
    failLoad(name, std::string("cannot read OpenEXR image (") + e.what() + ")");
  }
  return t;
}

}  // namespace candela
