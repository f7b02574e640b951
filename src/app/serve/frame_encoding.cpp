#include "app/serve/frame_encoding.h"

#include <stb/stb_image_write.h>

#include <memory>
#include <stdexcept>

#include "image/tonemap.h"

namespace candela {

DisplayImage displayImage(const Image& linear, const DisplaySettings& display) {
  DisplayImage out{linear.width, linear.height, std::vector<uint8_t>(linear.pixels.size() * 3)};
  for (size_t i = 0; i < linear.pixels.size(); ++i) {
    const Vec3 c = toneMap(linear.pixels[i], display.exposure, display.toneMapper);
    out.rgb[3 * i + 0] = displayByte(c.x);
    out.rgb[3 * i + 1] = displayByte(c.y);
    out.rgb[3 * i + 2] = displayByte(c.z);
  }
  return out;
}

std::string encodePng(const DisplayImage& image) {
  std::string png;
  auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), size_t(size));
  };
  if (!stbi_write_png_to_func(append, &png, int(image.width), int(image.height), 3, image.rgb.data(),
                              int(image.width) * 3))
    throw std::runtime_error("the PNG could not be encoded");
  return png;
}

}  // namespace candela
