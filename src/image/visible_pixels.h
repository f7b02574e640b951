#pragma once
#include "image/display_settings.h"
#include "image/image.h"

namespace candela {

// The fraction of the image's pixels that show other than black once tone mapped as an 8-bit image is written
// (writeImage): those with a channel of 1 or more of 255.
double visiblePixelFraction(const Image& image, const DisplaySettings& display);

// Whether an image shows almost nothing: fewer than 1% of its pixels are visible.
bool looksUnlit(const Image& image, const DisplaySettings& display);

}  // namespace candela
