#pragma once
// The body of the texture fuzz targets (fuzz_png, fuzz_jpeg): the header, then decoding at full size and at
// about half size (the area-averaging path), as TextureTable does.
#include <cstddef>
#include <cstdint>

#include "io/images/image_decoding.h"
#include "io/images/jpeg_decoding.h"
#include "io/images/png_decoding.h"
#include "io/load_diagnostics.h"

namespace candela::fuzz {

// Larger images are valid inputs that take the same paths through the decoders and candela, only for longer: a
// 510-byte TGA of 51931x67 pixels took seconds to decode twice with the sanitizers, and images of a million
// pixels (a few hundred bytes of PNG can claim them) kept the texture targets at 40 to 100 executions a second.
// The header checks (inspectImage) still run on every input.
constexpr uint64_t kMaxFuzzedPixels = uint64_t(1) << 16;

// `isFormat` keeps the target on its own format: without it, most mutations became TGA images (which have no
// signature), so the PNG and JPEG targets spent their time in stb_image's TGA reader, which fuzz_hdr covers.
inline void decodeTexture(const char* name, const uint8_t* data, size_t size,
                          bool (*isFormat)(const uint8_t*, size_t)) {
  if (!isFormat(data, size)) return;
  try {
    const ImageInfo info = inspectImage(name, data, size);
    if (uint64_t(info.width) * info.height > kMaxFuzzedPixels) return;
    decodeImage(name, data, size, true);
    decodeImage(name, data, size, true, (info.width + 1) / 2, (info.height + 2) / 3);
  } catch (const LoadError&) {
  }
}

}  // namespace candela::fuzz
