#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "app/interactive/post_settings.h"
#include "image/image.h"

namespace candela {

// 8-bit sRGB pixels, row-major, top row first, three bytes a pixel.
struct DisplayImage {
  uint32_t width = 0, height = 0;
  std::vector<uint8_t> rgb;
};

// The accumulated (perhaps denoised) image as the viewer's window would show it: through the CPU bilateral
// filter when it is on, then exposure and tone mapping (image/tonemap.h).
DisplayImage displayImage(const Image& accumulated, const PostSettings& post);

// Compressed with libjpeg-turbo at `quality` (1 to 100). Throws std::runtime_error with libjpeg-turbo's reason.
std::string encodeJpeg(const DisplayImage& image, int quality);
// Lossless, for the screenshot the browser downloads.
std::string encodePng(const DisplayImage& image);

}  // namespace candela
