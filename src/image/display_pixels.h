#pragma once
// A display frame: the 8-bit sRGB pixels a screen or a browser shows of linear radiance, after exposure and tone
// mapping, optionally downscaled by an integer divisor. The CPU version, parallel over rows with TBB; the OptiX
// backend's CUDA version (backends/optix/display_pixels.cu) runs the same per-pixel code (image/display_kernel.h)
// and gives the same bytes.
#include <cstdint>

#include "image/display_kernel.h"
#include "image/display_settings.h"

namespace candela {

struct DisplaySize {
  uint32_t width = 0, height = 0;
};

// The frame of a width x height image downscaled by `divisor`: (width / divisor) x (height / divisor), rounded
// down, each output pixel the mean of a divisor x divisor block of the linear values (before tone mapping). The
// last width % divisor columns and height % divisor rows are left out: a caller that wants all of the picture
// renders a multiple of the divisor. This is what rendering at 1 / divisor of the size gives in expectation, the
// way candela serve shrinks its preview. Throws std::invalid_argument for a divisor of 0 or one that leaves no pixel.
DisplaySize displaySize(uint32_t width, uint32_t height, uint32_t divisor);

// The display settings as the per-pixel code takes them: the exposure as a factor, exp2f(exposure), as toneMap
// computes it.
DisplayMapping displayMapping(const DisplaySettings& display);

// Writes the frame of `source` into `rgb`, three bytes a pixel, row-major, top row first, displaySize's pixels:
// each channel displayByte(toneMap(...)) (image/tonemap.h) of the box mean, byte for byte.
void writeDisplayPixels(const LinearPixels& source, const DisplaySettings& display, uint32_t divisor, uint8_t* rgb);

}  // namespace candela
