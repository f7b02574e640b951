#pragma once
// The arithmetic of a display frame (image/display_pixels.h) per pixel, shared by the CPU version and the CUDA one
// (backends/optix/display_pixels.cu), which therefore give the same bytes.
#include <cstdint>

#include "image/srgb_bytes.h"
#include "image/tonemap.h"
#include "kernel/film.h"

namespace candela {

// Linear radiance in memory, host or device: an image of means (samples null), or a film's sums with their sample
// counts (kernel/film.h's meanAt), row-major, top row first.
struct LinearPixels {
  const Vec3* values = nullptr;
  const uint32_t* samples = nullptr;
  uint32_t width = 0, height = 0;
};

// How the display shows a channel: times `scale` (exp2f of the exposure in stops), then the tone mapper.
struct DisplayMapping {
  float scale = 1.0f;
  ToneMapper mapper = ToneMapper::AcesFilmic;
};

// The mean of the divisor x divisor pixels whose top left one is (x * divisor, y * divisor), added row by row, left
// to right; at divisor 1 the pixel's own mean.
CANDELA_FN Vec3 boxMean(const LinearPixels& source, uint32_t x, uint32_t y, uint32_t divisor) {
  Vec3 sum{};
  for (uint32_t dy = 0; dy < divisor; ++dy) {
    const size_t row = size_t(y * divisor + dy) * source.width + size_t(x) * divisor;
    for (uint32_t dx = 0; dx < divisor; ++dx) sum += meanAt(source.values, source.samples, row + dx);
  }
  return sum / float(divisor * divisor);
}

// What toneMap (image/tonemap.h) gives of a channel of radiance times the exposure's scale before linearToSrgb's
// powf: in [0, 1], NaN (an infinite channel through a curve) as 0, as toneMap's clampf has it. The clamps are
// comparisons rather than fminf and fmaxf, which compilers do not vectorise; they give the same values, except
// that -0 becomes +0, whose byte is the same.
CANDELA_FN float displayValue(float x, ToneMapper mapper) {
  if (mapper == ToneMapper::AcesFilmic) x = acesFilmicUnclamped(x);
  if (mapper == ToneMapper::Reinhard) {
    x = x > 0.0f ? x : 0.0f;
    x = x / (1.0f + x);
  }
  x = x > 0.0f ? x : 0.0f;
  return x < 1.0f ? x : 1.0f;
}

// The three bytes of output pixel (x, y): displayByte(toneMap(...)) of its box mean.
CANDELA_FN void writeDisplayPixel(const LinearPixels& source, uint32_t x, uint32_t y, uint32_t divisor,
                                  const DisplayMapping& mapping, const SrgbByteTable& table, uint8_t* rgb) {
  const Vec3 c = boxMean(source, x, y, divisor) * mapping.scale;
  rgb[0] = srgbByte(table, displayValue(c.x, mapping.mapper));
  rgb[1] = srgbByte(table, displayValue(c.y, mapping.mapper));
  rgb[2] = srgbByte(table, displayValue(c.z, mapping.mapper));
}

}  // namespace candela
