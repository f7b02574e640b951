#include "image/visible_pixels.h"

#include "image/tonemap.h"

namespace candela {

double visiblePixelFraction(const Image& image, const DisplaySettings& display) {
  if (image.pixels.empty()) return 0.0;
  size_t visible = 0;
  for (const Vec3& pixel : image.pixels) {
    const Vec3 c = toneMap(pixel, display.exposure, display.toneMapper);
    if (displayByte(c.x) > 0 || displayByte(c.y) > 0 || displayByte(c.z) > 0) ++visible;
  }
  return double(visible) / double(image.pixels.size());
}

bool looksUnlit(const Image& image, const DisplaySettings& display) {
  return visiblePixelFraction(image, display) < 0.01;
}

}  // namespace candela
