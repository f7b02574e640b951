#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "app/interactive/frame_images.h"
#include "image/image.h"
#include "io/images/image_io.h"

namespace candela {

// 8-bit sRGB pixels, row-major, top row first, three bytes a pixel.
struct DisplayImage {
  uint32_t width = 0, height = 0;
  std::vector<uint8_t> rgb;
};

// A linear image as the viewer's window would show it: through exposure and tone mapping (image/tonemap.h).
DisplayImage displayImage(const Image& linear, const DisplaySettings& display);
// A rendered frame as the browser gets it: denoised, through the bilateral filter with the emission kept apart
// (FrameImages::filtered), tone mapped.
DisplayImage displayImage(FrameImages& frame);

// Compressed with libjpeg-turbo at `quality` (1 to 100). Throws std::runtime_error with libjpeg-turbo's reason.
std::string encodeJpeg(const DisplayImage& image, int quality);
// Lossless, for the screenshot the browser downloads.
std::string encodePng(const DisplayImage& image);

}  // namespace candela
