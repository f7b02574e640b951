#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "image/texture.h"

namespace candela {

// Largest decoded image accepted, so that a forged header cannot make a loader allocate without bound.
constexpr size_t kMaxDecodedImageBytes = size_t(1) << 31;
// Most pixels any accepted format can encode per byte of file (1-bit PNG at deflate's best ratio); a header
// that claims more describes data that is not there, and decoding it would only burn time.
constexpr double kMaxPixelsPerByte = 8.0 * 1032.0;

// What an image's header says: its size and the channels it decodes to.
struct ImageInfo {
  uint32_t width = 0;
  uint32_t height = 0;
  uint32_t channels = 4;
  bool hdr = false;  // decodes to floats
};

// Reads the header of a PNG, JPEG, WebP, TGA, BMP or Radiance HDR image held in memory, decoding no pixels. Throws
// LoadError naming `name` when it is not such an image or its header is absurd: no pixels, or more than the file
// can hold.
ImageInfo inspectImage(const std::string& name, const uint8_t* data, size_t size);

// Decodes such an image: PNG through libpng, JPEG through libjpeg-turbo, WebP through libwebp, the others through
// stb_image. 8-bit
// images keep their bytes: one channel for grey images, RGBA otherwise; `srgb` records how their colours are
// encoded. Radiance HDR images become float RGBA. Throws LoadError naming `name` when the data is not a readable
// image. The second form decodes to a smaller size (at most the image's own in each direction), each pixel the
// mean of those it covers; PNG (unless interlaced) and JPEG then never hold the full-size image.
Texture decodeImage(const std::string& name, const uint8_t* data, size_t size, bool srgb);
Texture decodeImage(const std::string& name, const uint8_t* data, size_t size, bool srgb, uint32_t targetWidth,
                    uint32_t targetHeight);

// A float RGB image for an environment: Radiance .hdr through stb_image, OpenEXR .exr through OpenEXR.
Texture loadEnvironmentImage(const std::string& path);

// For the decoders: fail unless a header's size is plausible for a file of `fileSize` bytes, and unless the
// decoded image fits kMaxDecodedImageBytes.
void checkImageHeader(const std::string& name, uint64_t width, uint64_t height, size_t fileSize);
void checkDecodedSize(const std::string& name, uint64_t width, uint64_t height, uint64_t bytesPerPixel);
// Radiance HDR and the float images of OpenEXR may hold NaN, infinite or negative values that would poison
// every estimate that sees them; they become 0. Returns how many.
size_t zeroInvalidFloats(std::vector<float>& floats);

}  // namespace candela
