#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "kernel/texture.h"

namespace candela {

// An image a material samples. 8-bit images keep their bytes; `srgb` says whether they encode sRGB colour.
struct Texture {
  std::string name;  // file path or a description, for messages
  uint32_t width = 0;
  uint32_t height = 0;
  uint32_t channels = 4;
  bool srgb = false;
  TextureWrap wrapU = TextureWrap::Repeat;  // across the columns
  TextureWrap wrapV = TextureWrap::Repeat;  // down the rows
  std::vector<uint8_t> bytes;               // 8-bit images: width * height * channels
  std::vector<float> floats;                // float images: width * height * channels
};

}  // namespace candela
