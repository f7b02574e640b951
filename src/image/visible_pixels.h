#pragma once
#include "image/image.h"
#include "image/image_io.h"

namespace candela {

// The fraction of the image's pixels that show other than black once tone mapped as an 8-bit image is written
// (writeImage): those with a channel of 1 or more of 255.
double visiblePixelFraction(const Image& image, const DisplaySettings& display);

// Whether an image of a scene that has light shows almost nothing: fewer than 1% of its pixels are visible. A
// camera inside a closed object, say, would otherwise give a black image without a word (a scene without light is
// named when it loads).
bool looksUnlit(const Image& image, const DisplaySettings& display);

// What render says of such an image.
constexpr const char* kUnlitImageWarning =
    "candela: warning: the image is black in more than 99% of its pixels: little of the scene's light reaches what "
    "the camera sees (is the camera inside a closed object? --camera chooses another, --exposure brightens the image)";

}  // namespace candela
