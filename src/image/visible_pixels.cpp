#include "image/visible_pixels.h"

#include "image/tonemap.h"

namespace candela {

double visiblePixelFraction(const Image& image, const DisplaySettings& display) {
  if (image.pixels.empty()) return 0.0;
  size_t visible = 0;
  for (const Vec3& pixel : image.pixels) {
    const Vec3 c = toneMap(pixel, display.exposure, display.toneMapper);
    // As writeToneMappedPng quantises: a channel below half a step is 0.
    if (c.x * 255.0f + 0.5f >= 1.0f || c.y * 255.0f + 0.5f >= 1.0f || c.z * 255.0f + 0.5f >= 1.0f) ++visible;
  }
  return double(visible) / double(image.pixels.size());
}

bool looksUnlit(const Image& image, const DisplaySettings& display) {
  return visiblePixelFraction(image, display) < 0.01;
}

}  // namespace candela
