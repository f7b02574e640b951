#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

#include "io/images/image_decoding.h"

namespace candela {

// A RIFF container holding WebP ("RIFF", size, "WEBP").
bool isWebp(const uint8_t* data, size_t size);

// A WebP's size from its header (libwebp), without decoding the pixels; always four channels.
ImageInfo webpInfo(const std::string& name, const uint8_t* data, size_t size);

// Decodes a WebP (lossy or lossless; of an animation, the first frame) through libwebp to RGBA, opaque alpha where
// it has none, area averaged down to `targetWidth` x `targetHeight` (at most its own size). Throws LoadError
// naming `name`.
Texture decodeWebp(const std::string& name, const uint8_t* data, size_t size, uint32_t targetWidth,
                   uint32_t targetHeight);

}  // namespace candela
