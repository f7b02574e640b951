#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

#include "scene/scene.h"

namespace candela {

// Largest decoded image accepted, so that a forged header cannot make a loader allocate without bound.
constexpr size_t kMaxDecodedImageBytes = size_t(1) << 31;
// Most pixels any accepted format can encode per byte of file (1-bit PNG at deflate's best ratio); a header
// that claims more describes data that is not there, and decoding it would only burn time.
constexpr double kMaxPixelsPerByte = 8.0 * 1032.0;

// Decodes a PNG, JPEG, TGA, BMP or Radiance HDR image held in memory. 8-bit images keep
// their bytes: one channel for grey images, RGBA otherwise; `srgb` records how their colours are encoded.
// Radiance HDR images become float RGBA. Throws LoadError naming `name` when the data is not a readable image.
Texture decodeImage(const std::string& name, const uint8_t* data, size_t size, bool srgb);

// A float RGB image for an environment: Radiance .hdr through stb_image, OpenEXR .exr through OpenEXR.
Texture loadEnvironmentImage(const std::string& path);

}  // namespace candela
