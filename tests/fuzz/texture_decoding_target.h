#pragma once
// The body of the texture fuzz targets (fuzz_png, fuzz_jpeg): the header, then decoding at full size and at
// about half size (the area-averaging path), as TextureTable does.
#include <cstddef>
#include <cstdint>

#include "scene/loaders/image_decoding.h"
#include "scene/loaders/load_diagnostics.h"

namespace candela::fuzz {

inline void decodeTexture(const char* name, const uint8_t* data, size_t size) {
  try {
    const ImageInfo info = inspectImage(name, data, size);
    // Larger images are valid inputs but only slow the fuzzer down: a 510-byte TGA of 51931x67 pixels takes
    // seconds to decode twice with the sanitizers, and timed out on a loaded machine.
    if (uint64_t(info.width) * info.height > (uint64_t(1) << 20)) return;
    decodeImage(name, data, size, true);
    decodeImage(name, data, size, true, (info.width + 1) / 2, (info.height + 2) / 3);
  } catch (const LoadError&) {
  }
}

}  // namespace candela::fuzz
