#include "image/display_pixels.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace candela {

namespace {

// A row at a time in three passes, each a loop of its own: the box means times the exposure's scale, then the
// tone curve over all the row's channels (a loop compilers vectorise), then the table look-ups. The mapper and a
// divisor of 1 are template parameters so that each loop compiles without their branches.
template <ToneMapper kMapper, bool kUnitDivisor>
void writeRows(const LinearPixels& source, DisplaySize size, uint32_t divisor, float scale,
               const tbb::blocked_range<uint32_t>& rows, uint8_t* rgb) {
  const SrgbByteTable& table = srgbByteTable();
  const size_t channels = size_t(size.width) * 3;
  std::vector<float> values(channels);
  for (uint32_t y = rows.begin(); y < rows.end(); ++y) {
    for (uint32_t x = 0; x < size.width; ++x) {
      const Vec3 c = boxMean(source, x, y, kUnitDivisor ? 1 : divisor) * scale;
      values[3 * size_t(x) + 0] = c.x;
      values[3 * size_t(x) + 1] = c.y;
      values[3 * size_t(x) + 2] = c.z;
    }
    for (size_t i = 0; i < channels; ++i) values[i] = displayValue(values[i], kMapper);
    uint8_t* out = rgb + size_t(y) * channels;
    for (size_t i = 0; i < channels; ++i) out[i] = srgbByte(table, values[i]);
  }
}

template <ToneMapper kMapper>
void writeFrame(const LinearPixels& source, DisplaySize size, uint32_t divisor, float scale, uint8_t* rgb) {
  // Rows in blocks of at least 8: enough work per task for TBB's overhead to vanish.
  tbb::parallel_for(tbb::blocked_range<uint32_t>(0, size.height, 8), [&](const tbb::blocked_range<uint32_t>& rows) {
    if (divisor == 1)
      writeRows<kMapper, true>(source, size, divisor, scale, rows, rgb);
    else
      writeRows<kMapper, false>(source, size, divisor, scale, rows, rgb);
  });
}

}  // namespace

DisplaySize displaySize(uint32_t width, uint32_t height, uint32_t divisor) {
  if (divisor == 0) throw std::invalid_argument("a display frame's divisor must be at least 1");
  const DisplaySize size{width / divisor, height / divisor};
  if (size.width == 0 || size.height == 0)
    throw std::invalid_argument("a divisor of " + std::to_string(divisor) + " leaves no pixel of a " +
                                std::to_string(width) + "x" + std::to_string(height) + " image");
  return size;
}

DisplayMapping displayMapping(const DisplaySettings& display) { return {exp2f(display.exposure), display.toneMapper}; }

void writeDisplayPixels(const LinearPixels& source, const DisplaySettings& display, uint32_t divisor, uint8_t* rgb) {
  const DisplaySize size = displaySize(source.width, source.height, divisor);
  const DisplayMapping mapping = displayMapping(display);
  switch (mapping.mapper) {
    case ToneMapper::AcesFilmic: return writeFrame<ToneMapper::AcesFilmic>(source, size, divisor, mapping.scale, rgb);
    case ToneMapper::Clamp: return writeFrame<ToneMapper::Clamp>(source, size, divisor, mapping.scale, rgb);
    case ToneMapper::Reinhard: return writeFrame<ToneMapper::Reinhard>(source, size, divisor, mapping.scale, rgb);
  }
  throw std::invalid_argument("unknown tone mapper");
}

}  // namespace candela
