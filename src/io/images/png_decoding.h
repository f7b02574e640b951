#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

#include "io/images/image_decoding.h"

namespace candela {

bool isPng(const uint8_t* data, size_t size);

// A PNG's size and channels from its header (libpng), without decoding the pixels.
ImageInfo pngInfo(const std::string& name, const uint8_t* data, size_t size);

// Decodes a PNG through libpng, area averaged down to `targetWidth` x `targetHeight` (at most its own size):
// 8 bits per channel (16-bit samples keep their high byte), one channel for grey images (transparency dropped),
// RGBA otherwise (palettes expanded, tRNS as alpha, opaque alpha added). Throws LoadError naming `name`.
Texture decodePng(const std::string& name, const uint8_t* data, size_t size, uint32_t targetWidth,
                  uint32_t targetHeight);

}  // namespace candela
