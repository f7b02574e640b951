#pragma once
#include <string>
#include <vector>

#include "image/image.h"
#include "image/tonemap.h"

namespace candela {

struct DisplaySettings {
  float exposure = 0.0f;  // stops
  ToneMapper toneMapper = ToneMapper::AcesFilmic;
};

// "aces", "clamp" or "reinhard"; parseToneMapper throws std::invalid_argument for other names.
const char* toneMapperName(ToneMapper mapper);
ToneMapper parseToneMapper(const std::string& name);

// Writes by extension: .png (tone mapped, sRGB, 8 bit), .exr (linear float RGB), .pfm (linear float).
// Throws std::runtime_error with a sentence naming the file when it cannot.
void writeImage(const std::string& path, const Image& image, const DisplaySettings& display);

// One float channel of an EXR file: `base` points at the top-left pixel's value, rows are packed.
struct ExrChannel {
  std::string name;  // "R", or "layer.R" for a layer
  const char* base;
  size_t xStride;  // bytes from one pixel's value to the next
};
void writeExrChannels(const std::string& path, uint32_t width, uint32_t height,
                      const std::vector<ExrChannel>& channels);

// True when writeImage knows the extension of `path`.
bool isSupportedImageExtension(const std::string& path);

}  // namespace candela
