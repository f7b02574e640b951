#include "io/images/webp_decoding.h"

#include <webp/decode.h>

#include <cstring>
#include <vector>

#include "io/images/area_downscaler.h"
#include "io/images/downscaled_texture.h"
#include "io/load_diagnostics.h"

namespace candela {

bool isWebp(const uint8_t* data, size_t size) {
  return size >= 12 && std::memcmp(data, "RIFF", 4) == 0 && std::memcmp(data + 8, "WEBP", 4) == 0;
}

ImageInfo webpInfo(const std::string& name, const uint8_t* data, size_t size) {
  int width = 0, height = 0;
  if (!WebPGetInfo(data, size, &width, &height)) failLoad(name, "not a readable WebP image");
  if (width <= 0 || height <= 0) failLoad(name, "image has no pixels");
  return {uint32_t(width), uint32_t(height), 4, false};
}

Texture decodeWebp(const std::string& name, const uint8_t* data, size_t size, uint32_t targetWidth,
                   uint32_t targetHeight) {
  const ImageInfo info = webpInfo(name, data, size);
  checkDecodedSize(name, info.width, info.height, 4);
  // libwebp decodes whole images only; the full-size pixels live until the area average is taken.
  const size_t stride = size_t(info.width) * 4;
  std::vector<uint8_t> pixels(stride * info.height);
  if (!WebPDecodeRGBAInto(data, size, pixels.data(), pixels.size(), int(stride)))
    failLoad(name, "cannot decode WebP image");
  AreaDownscaler<uint8_t> target(info.width, info.height, targetWidth, targetHeight, 4);
  for (uint32_t y = 0; y < info.height; ++y) target.addRow(pixels.data() + y * stride);
  return finishTexture(name, target);
}

}  // namespace candela
