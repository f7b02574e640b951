#include "io/images/image_decoding.h"

#include <stb/stb_image.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <memory>

#include "core/file_extension.h"
#include "io/file_bytes.h"
#include "io/images/area_downscaler.h"
#include "io/images/exr_decoding.h"
#include "io/images/jpeg_decoding.h"
#include "io/images/png_decoding.h"
#include "io/images/webp_decoding.h"
#include "io/load_budget.h"
#include "io/load_diagnostics.h"

namespace candela {

namespace {

struct StbFree {
  void operator()(void* p) const { stbi_image_free(p); }
};

// stb_image reads a truncated Radiance file as if the missing scanlines were black. Walking the scanline
// encoding (Greg Ward's run-length scheme, or flat RGBE) says whether the data is all there.
bool radianceDataComplete(const uint8_t* data, size_t size, int width, int height) {
  // The pixel data starts after the empty line that ends the header and the resolution line after it.
  size_t p = 0;
  for (int newlines = 0; p < size; ++p)
    if (data[p] == '\n') {
      bool emptyLine = p > 0 && data[p - 1] == '\n';
      if (newlines == 1) break;
      if (emptyLine) newlines = 1;
    }
  ++p;
  for (int y = 0; y < height; ++y) {
    bool rle = width >= 8 && width < 32768 && p + 4 <= size && data[p] == 2 && data[p + 1] == 2 &&
               ((data[p + 2] << 8) | data[p + 3]) == width;
    if (!rle) {
      size_t rest = size_t(height - y) * size_t(width) * 4;
      return p <= size && size - p >= rest;
    }
    p += 4;
    for (int channel = 0; channel < 4; ++channel)
      for (int x = 0; x < width;) {
        if (p >= size) return false;
        int count = data[p++];
        if (count > 128) {
          count -= 128;
          ++p;
        } else {
          p += size_t(count);
        }
        if (count == 0 || p > size) return false;
        x += count;
      }
  }
  return true;
}

// TGA, BMP and Radiance HDR, which have no better decoder among the system's libraries.
ImageInfo stbInfo(const std::string& name, const uint8_t* data, size_t size) {
  if (size > size_t(INT_MAX)) failLoad(name, "image file is too large");
  int width = 0, height = 0, components = 0;
  if (!stbi_info_from_memory(data, int(size), &width, &height, &components))
    failLoad(name, std::string("not a readable image (") + stbi_failure_reason() + ")");
  if (width <= 0 || height <= 0) failLoad(name, "image has no pixels");
  const bool hdr = stbi_is_hdr_from_memory(data, int(size)) != 0;
  return {uint32_t(width), uint32_t(height), (components == 1 && !hdr) ? 1u : 4u, hdr};
}

template <typename Sample>
std::vector<Sample> downscaled(const Sample* pixels, const ImageInfo& info, uint32_t targetWidth,
                               uint32_t targetHeight) {
  AreaDownscaler<Sample> target(info.width, info.height, targetWidth, targetHeight, info.channels);
  for (uint32_t y = 0; y < info.height; ++y) target.addRow(pixels + size_t(y) * info.width * info.channels);
  return target.finish();
}

Texture decodeWithStb(const std::string& name, const uint8_t* data, size_t size, const ImageInfo& info,
                      uint32_t targetWidth, uint32_t targetHeight) {
  checkDecodedSize(name, info.width, info.height, info.channels * (info.hdr ? sizeof(float) : 1));
  const int len = int(size), channels = int(info.channels);
  int width = 0, height = 0, components = 0;
  Texture t;
  if (info.hdr) {
    if (!radianceDataComplete(data, size, int(info.width), int(info.height)))
      failLoad(name, "Radiance image is truncated");
    std::unique_ptr<float, StbFree> pixels(stbi_loadf_from_memory(data, len, &width, &height, &components, channels));
    if (!pixels) failLoad(name, std::string("cannot decode image (") + stbi_failure_reason() + ")");
    if (uint32_t(width) != info.width || uint32_t(height) != info.height) failLoad(name, "image size changed");
    t.floats = downscaled(pixels.get(), info, targetWidth, targetHeight);
    zeroInvalidFloats(t.floats);
  } else {
    std::unique_ptr<uint8_t, StbFree> pixels(stbi_load_from_memory(data, len, &width, &height, &components, channels));
    if (!pixels) failLoad(name, std::string("cannot decode image (") + stbi_failure_reason() + ")");
    if (uint32_t(width) != info.width || uint32_t(height) != info.height) failLoad(name, "image size changed");
    t.bytes = downscaled(pixels.get(), info, targetWidth, targetHeight);
  }
  t.name = name;
  t.width = targetWidth;
  t.height = targetHeight;
  t.channels = info.channels;
  return t;
}

Texture decodeAt(const std::string& name, const uint8_t* data, size_t size, bool srgb, const ImageInfo& info,
                 uint32_t targetWidth, uint32_t targetHeight) {
  targetWidth = std::clamp(targetWidth, 1u, info.width);
  targetHeight = std::clamp(targetHeight, 1u, info.height);
  chargeLoadMemory(uint64_t(targetWidth) * targetHeight * info.channels * (info.hdr ? sizeof(float) : 1), name,
                   "an image decoded at " + std::to_string(targetWidth) + "x" + std::to_string(targetHeight) +
                       " pixels");
  Texture t = isPng(data, size)    ? decodePng(name, data, size, targetWidth, targetHeight)
              : isJpeg(data, size) ? decodeJpeg(name, data, size, targetWidth, targetHeight)
              : isWebp(data, size) ? decodeWebp(name, data, size, targetWidth, targetHeight)
                                   : decodeWithStb(name, data, size, info, targetWidth, targetHeight);
  t.srgb = info.hdr ? false : srgb;
  return t;
}

}  // namespace

void checkImageHeader(const std::string& name, uint64_t width, uint64_t height, size_t fileSize) {
  if (width == 0 || height == 0) failLoad(name, "image has no pixels");
  if (double(width) * double(height) > kMaxPixelsPerByte * double(fileSize))
    failLoad(name, "image header claims " + std::to_string(width) + "x" + std::to_string(height) +
                       " pixels, more than the file can hold");
}

void checkDecodedSize(const std::string& name, uint64_t width, uint64_t height, uint64_t bytesPerPixel) {
  if (double(width) * double(height) * double(bytesPerPixel) > double(kMaxDecodedImageBytes))
    failLoad(name, "image of " + std::to_string(width) + "x" + std::to_string(height) +
                       " pixels is larger than the loader accepts");
}

size_t zeroInvalidFloats(std::vector<float>& floats) {
  size_t replaced = 0;
  for (float& f : floats)
    if (!std::isfinite(f) || f < 0.0f) {
      f = 0.0f;
      ++replaced;
    }
  return replaced;
}

ImageInfo inspectImage(const std::string& name, const uint8_t* data, size_t size) {
  if (size == 0) failLoad(name, "image file is empty");
  const ImageInfo info = isPng(data, size)    ? pngInfo(name, data, size)
                         : isJpeg(data, size) ? jpegInfo(name, data, size)
                         : isWebp(data, size) ? webpInfo(name, data, size)
                                              : stbInfo(name, data, size);
  checkImageHeader(name, info.width, info.height, size);
  return info;
}

Texture decodeImage(const std::string& name, const uint8_t* data, size_t size, bool srgb) {
  const ImageInfo info = inspectImage(name, data, size);
  return decodeAt(name, data, size, srgb, info, info.width, info.height);
}

Texture decodeImage(const std::string& name, const uint8_t* data, size_t size, bool srgb, uint32_t targetWidth,
                    uint32_t targetHeight) {
  return decodeAt(name, data, size, srgb, inspectImage(name, data, size), targetWidth, targetHeight);
}

Texture loadEnvironmentImage(const std::string& path) {
  std::vector<uint8_t> bytes = readFileBytes(path);
  if (lowerCaseExtension(path) == ".exr") return decodeExr(path, bytes.data(), bytes.size());
  if (!stbi_is_hdr_from_memory(bytes.data(), int(std::min(bytes.size(), size_t(INT_MAX)))))
    failLoad(path, "an environment map must be a Radiance .hdr or an OpenEXR .exr image");
  Texture rgba = decodeImage(path, bytes.data(), bytes.size(), false);
  Texture t;
  t.name = path;
  t.width = rgba.width;
  t.height = rgba.height;
  t.channels = 3;
  t.floats.resize(size_t(t.width) * t.height * 3);
  for (size_t i = 0; i < size_t(t.width) * t.height; ++i)
    for (int c = 0; c < 3; ++c) t.floats[3 * i + c] = rgba.floats[4 * i + c];
  return t;
}

}  // namespace candela
