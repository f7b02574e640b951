#pragma once
#include <cstdint>

#include "core/platform.h"

namespace candela {

// What a backend's closest-hit query returns; everything else is reconstructed by kernel code.
struct Hit {
  float t = 0.0f;
  float b1 = 0.0f, b2 = 0.0f;  // barycentrics of vertices 1 and 2
  uint32_t instanceId = 0;
  uint32_t primitiveId = 0;
};

}  // namespace candela
