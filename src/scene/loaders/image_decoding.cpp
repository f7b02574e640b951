#include "scene/loaders/image_decoding.h"

#include <stb/stb_image.h>

#include <OpenEXR/ImfArray.h>
#include <OpenEXR/ImfRgbaFile.h>

#include <algorithm>
#include <cmath>
#include <climits>
#include <filesystem>

#include "scene/loaders/file_bytes.h"
#include "scene/loaders/load_diagnostics.h"
#include "core/file_extension.h"

namespace candela {

namespace {

void checkSize(const std::string& name, int width, int height, size_t bytesPerPixel) {
  if (width <= 0 || height <= 0) failLoad(name, "image has no pixels");
  if (double(width) * double(height) * double(bytesPerPixel) > double(kMaxDecodedImageBytes))
    failLoad(name, "image of " + std::to_string(width) + "x" + std::to_string(height) +
                       " pixels is larger than the loader accepts");
}

struct StbFree {
  void operator()(void* p) const { stbi_image_free(p); }
};

// Radiance HDR and the float images of OpenEXR may hold NaN, infinite or negative values that would poison
// every estimate that sees them; they become 0.
size_t zeroInvalid(std::vector<float>& floats) {
  size_t replaced = 0;
  for (float& f : floats)
    if (!std::isfinite(f) || f < 0.0f) {
      f = 0.0f;
      ++replaced;
    }
  return replaced;
}

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

}  // namespace

Texture decodeImage(const std::string& name, const uint8_t* data, size_t size, bool srgb) {
  if (size == 0) failLoad(name, "image file is empty");
  if (size > size_t(INT_MAX)) failLoad(name, "image file is too large");
  int len = int(size), width = 0, height = 0, components = 0;
  if (!stbi_info_from_memory(data, len, &width, &height, &components))
    failLoad(name, std::string("not a readable image (") + stbi_failure_reason() + ")");
  bool hdr = stbi_is_hdr_from_memory(data, len) != 0;
  if (double(width) * double(height) > kMaxPixelsPerByte * double(size))
    failLoad(name, "image header claims " + std::to_string(width) + "x" + std::to_string(height) +
                       " pixels, more than the file can hold");
  int channels = (components == 1 && !hdr) ? 1 : 4;
  checkSize(name, width, height, size_t(channels) * (hdr ? sizeof(float) : 1));

  Texture t;
  t.name = name;
  t.channels = uint32_t(channels);
  if (hdr) {
    if (!radianceDataComplete(data, size, width, height)) failLoad(name, "Radiance image is truncated");
    std::unique_ptr<float, StbFree> pixels(stbi_loadf_from_memory(data, len, &width, &height, &components, channels));
    if (!pixels) failLoad(name, std::string("cannot decode image (") + stbi_failure_reason() + ")");
    t.floats.assign(pixels.get(), pixels.get() + size_t(width) * height * channels);
    zeroInvalid(t.floats);
    t.srgb = false;
  } else {
    std::unique_ptr<uint8_t, StbFree> pixels(stbi_load_from_memory(data, len, &width, &height, &components, channels));
    if (!pixels) failLoad(name, std::string("cannot decode image (") + stbi_failure_reason() + ")");
    t.bytes.assign(pixels.get(), pixels.get() + size_t(width) * height * channels);
    t.srgb = srgb;
  }
  t.width = uint32_t(width);
  t.height = uint32_t(height);
  return t;
}

namespace {

Texture loadExr(const std::string& path) {
  Texture t;
  t.name = path;
  t.channels = 3;
  try {
    Imf::RgbaInputFile file(path.c_str());
    Imath::Box2i window = file.dataWindow();
    int width = window.max.x - window.min.x + 1, height = window.max.y - window.min.y + 1;
    checkSize(path, width, height, sizeof(Imf::Rgba) + 3 * sizeof(float));
    Imf::Array2D<Imf::Rgba> pixels(height, width);
    file.setFrameBuffer(&pixels[0][0] - window.min.x - window.min.y * width, 1, size_t(width));
    file.readPixels(window.min.y, window.max.y);
    t.width = uint32_t(width);
    t.height = uint32_t(height);
    t.floats.resize(size_t(width) * height * 3);
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const Imf::Rgba& p = pixels[y][x];
        float* out = &t.floats[(size_t(y) * width + x) * 3];
        out[0] = p.r;
        out[1] = p.g;
        out[2] = p.b;
      }
  } catch (const LoadError&) {
    throw;
  } catch (const std::exception& e) {
    failLoad(path, std::string("cannot read OpenEXR image (") + e.what() + ")");
  }
  zeroInvalid(t.floats);
  return t;
}

}  // namespace

Texture loadEnvironmentImage(const std::string& path) {
  std::string ext = lowerCaseExtension(path);
  if (ext == ".exr") {
    const InputFile checked(path);  // OpenEXR opens it by name: a FIFO would block it, a device feed it forever
    return loadExr(path);
  }
  std::vector<uint8_t> bytes = readFileBytes(path);
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
