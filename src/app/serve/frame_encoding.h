#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "image/image.h"
#include "io/images/image_io.h"

namespace candela {

// 8-bit sRGB pixels, row-major, top row first, three bytes a pixel.
struct DisplayImage {
  uint32_t width = 0, height = 0;
  std::vector<uint8_t> rgb;
};

// A linear image as the viewer's window would show it: through exposure and tone mapping (image/tonemap.h); the
// screenshot the page downloads.
DisplayImage displayImage(const Image& linear, const DisplaySettings& display);

// Lossless, for the screenshot the browser downloads.
std::string encodePng(const DisplayImage& image);

}  // namespace candela
