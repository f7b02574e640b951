#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

#include "io/images/image_decoding.h"

namespace candela {

bool isJpeg(const uint8_t* data, size_t size);

// A JPEG's size and channels from its header (libjpeg-turbo), without decoding the pixels.
ImageInfo jpegInfo(const std::string& name, const uint8_t* data, size_t size);

// Decodes a JPEG through libjpeg-turbo, area averaged down to `targetWidth` x `targetHeight` (at most its own
// size; the DCT does the first factors of two): one channel for greyscale, else RGBA with opaque alpha (CMYK
// converted). Throws LoadError naming `name`.
Texture decodeJpeg(const std::string& name, const uint8_t* data, size_t size, uint32_t targetWidth,
                   uint32_t targetHeight);

}  // namespace candela
