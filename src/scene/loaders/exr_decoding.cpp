#include "scene/loaders/exr_decoding.h"

#include <OpenEXR/ImfArray.h>
#include <OpenEXR/ImfRgbaFile.h>

#include "image/exr_memory_stream.h"
#include "scene/loaders/image_decoding.h"
#include "scene/loaders/load_diagnostics.h"

namespace candela {

Texture decodeExr(const std::string& name, const uint8_t* data, size_t size) {
  Texture t;
  t.name = name;
  t.channels = 3;
  try {
    ExrMemoryStream stream(name, data, size);
    Imf::RgbaInputFile file(stream);
    const Imath::Box2i window = file.dataWindow();
    // The window may lie anywhere in int's range: its size and offsets are computed in 64 bits.
    const int64_t width = int64_t(window.max.x) - window.min.x + 1;
    const int64_t height = int64_t(window.max.y) - window.min.y + 1;
    if (width <= 0 || height <= 0 || width > INT32_MAX || height > INT32_MAX)
      failLoad(name, "OpenEXR data window has no pixels");
    checkImageHeader(name, uint64_t(width), uint64_t(height), size);
    checkDecodedSize(name, uint64_t(width), uint64_t(height), sizeof(Imf::Rgba) + 3 * sizeof(float));
    Imf::Array2D<Imf::Rgba> pixels(height, width);
    // OpenEXR addresses pixel (x, y) of the window at base + x + y * width; base itself lies outside the array
    // unless the window starts at the origin, so it is computed as an address, not by pointer arithmetic.
    const int64_t originOffset = int64_t(window.min.x) + int64_t(window.min.y) * width;
    const uintptr_t base = reinterpret_cast<uintptr_t>(&pixels[0][0]) - uintptr_t(originOffset) * sizeof(Imf::Rgba);
    file.setFrameBuffer(reinterpret_cast<Imf::Rgba*>(base), 1, size_t(width));
    file.readPixels(window.min.y, window.max.y);
    t.width = uint32_t(width);
    t.height = uint32_t(height);
    t.floats.resize(size_t(width) * size_t(height) * 3);
    for (int64_t y = 0; y < height; ++y)
      for (int64_t x = 0; x < width; ++x) {
        const Imf::Rgba& p = pixels[y][x];
        float* out = &t.floats[(size_t(y) * size_t(width) + size_t(x)) * 3];
        out[0] = p.r;
        out[1] = p.g;
        out[2] = p.b;
      }
  } catch (const LoadError&) {
    throw;
  } catch (const std::exception& e) {
    failLoad(name, std::string("cannot read OpenEXR image (") + e.what() + ")");
  }
  zeroInvalidFloats(t.floats);
  return t;
}

}  // namespace candela
