#pragma once
#include "core/math.h"

namespace candela {

struct BsdfSample {
  Vec3 wi;           // sampled incident direction, local frame
  Vec3 f;            // BSDF value for (wo, wi)
  float pdf = 0.0f;  // solid-angle density of wi; for delta lobes the discrete probability
  bool isDelta = false;
  bool valid = false;
};

}  // namespace candela
