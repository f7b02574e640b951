#include "app/serve/frame_encoding.h"

#include <stb/stb_image_write.h>

#include <memory>
#include <stdexcept>

#include "image/display_pixels.h"

namespace candela {

DisplayImage displayImage(const Image& linear, const DisplaySettings& display) {
  DisplayImage out{linear.width, linear.height, std::vector<uint8_t>(linear.pixels.size() * 3)};
  if (!linear.pixels.empty())
    writeDisplayPixels({linear.pixels.data(), nullptr, linear.width, linear.height}, display, 1, out.rgb.data());
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
