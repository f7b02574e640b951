#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>

#include "image/texture.h"

namespace candela {

// Decodes an OpenEXR image held in memory to float RGB (luminance-chroma and grey images converted by OpenEXR),
// with NaN, infinite and negative values made 0. Any data window is accepted whose size fits the loader's
// limits, wherever it lies: at most `maxPixels` pixels, plausible for the file's size, and within
// kMaxDecodedImageBytes, all checked on the header before any pixel is read. The pixels are read in bands of rows
// and area averaged down to at most `maxSide` pixels a side (the aspect ratio kept), so that only the result and
// one band are held; both are charged to the load's memory budget first. `fileSize`, when given, receives the
// image's width and height in the file. Throws LoadError naming `name`.
Texture decodeExr(const std::string& name, const uint8_t* data, size_t size, uint64_t maxPixels = UINT64_MAX,
                  uint32_t maxSide = UINT32_MAX, std::pair<uint32_t, uint32_t>* fileSize = nullptr);

// The checks decodeExr makes before OpenEXR reads anything, for every other reader of OpenEXR files: every
// attribute lies within the file and has the size it declares (OpenEXR allocates what an attribute claims), and
// with `checkDataWindows`, every data window is within the image limits (a reader of other files than images
// checks their windows itself). Throws LoadError naming `name`.
void checkExrHeaders(const std::string& name, const uint8_t* data, size_t size, uint64_t maxPixels = UINT64_MAX,
                     bool checkDataWindows = true);

}  // namespace candela
