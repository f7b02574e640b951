#pragma once
#include <cstdint>

namespace candela {

struct RenderSettings {
  uint32_t width = 512;
  uint32_t height = 512;
  uint32_t maxDepth = 8;       // path segments after the camera ray; 1 = direct lighting only
  uint32_t rouletteDepth = 3;  // bounces before Russian roulette may end a path
  uint32_t seed = 0;
};

}  // namespace candela
