#pragma once
#include <cstdint>
#include <string>

#include "image/texture.h"
#include "io/images/area_downscaler.h"

namespace candela {

// The 8-bit texture `name` that a decoder has fed row by row into `image`, once every source row is in.
inline Texture finishTexture(const std::string& name, AreaDownscaler<uint8_t>& image) {
  Texture t;
  t.name = name;
  t.width = image.targetWidth();
  t.height = image.targetHeight();
  t.channels = image.channels();
  t.bytes = image.finish();
  return t;
}

}  // namespace candela
