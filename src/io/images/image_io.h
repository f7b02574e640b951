#pragma once
#include <string>
#include <utility>
#include <vector>

#include "image/display_settings.h"
#include "image/image.h"
#include "io/atomic_file.h"

namespace candela {

// Writes by extension: .png (tone mapped, sRGB, 8 bit), .exr (linear float RGB), .pfm (linear float).
// Every writer here replaces its file atomically (io/atomic_file.h): after a failure the previous file is
// intact. Throws WriteError with a sentence naming the file when it cannot.
void writeImage(const std::string& path, const Image& image, const DisplaySettings& display);
// The same into an open AtomicFile, by the extension of its target, for callers that commit several files
// together; the caller commits.
void writeImageTo(AtomicFile& file, const Image& image, const DisplaySettings& display);

// An 8-bit PNG of 1 to 4 channels; rows `strideBytes` apart (negative: bottom row first in memory).
void writePngFile(const std::string& path, int width, int height, int channels, const uint8_t* pixels, int strideBytes);
void writePngTo(AtomicFile& file, int width, int height, int channels, const uint8_t* pixels, int strideBytes);

// One channel of an EXR file: `base` points at the top-left pixel's value, rows are packed.
struct ExrChannel {
  std::string name;  // "R", or "layer.R" for a layer
  const char* base;
  size_t xStride;       // bytes from one pixel's value to the next
  bool isUint = false;  // 32-bit unsigned integers rather than 32-bit floats
};
// Text attributes of an EXR header, name and value.
using ExrAttributes = std::vector<std::pair<std::string, std::string>>;
void writeExrChannels(const std::string& path, uint32_t width, uint32_t height,
                      const std::vector<ExrChannel>& channels);
// Into an open AtomicFile, finished (on disk and closed) but not committed.
void writeExrChannelsTo(AtomicFile& file, uint32_t width, uint32_t height, const std::vector<ExrChannel>& channels,
                        const ExrAttributes& attributes = {});

// True when writeImage knows the extension of `path`.
bool isSupportedImageExtension(const std::string& path);

}  // namespace candela
