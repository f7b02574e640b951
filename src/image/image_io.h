#pragma once
#include <string>

#include "image/image.h"
#include "image/tonemap.h"

namespace candela {

struct DisplaySettings {
  float exposure = 0.0f;  // stops
  ToneMapper toneMapper = ToneMapper::AcesFilmic;
};

// Writes by extension: .png (tone mapped, sRGB, 8 bit), .exr (linear float RGB), .pfm (linear float).
// Throws std::runtime_error with a sentence naming the file when it cannot.
void writeImage(const std::string& path, const Image& image, const DisplaySettings& display);

// True when writeImage knows the extension of `path`.
bool isSupportedImageExtension(const std::string& path);

}  // namespace candela
