#pragma once
#include "core/math.h"

namespace candela {

// Directions are in the local shading frame: the normal is +z and wo always lies on the +z side (the Bsdf
// flips its frame towards wo), so wi.z < 0 means transmission.
struct BsdfSample {
  Vec3 wi;           // sampled incident direction, local frame
  Vec3 f;            // BSDF value for (wo, wi); for delta lobes the value that makes f |cos| / pdf the weight
  float pdf = 0.0f;  // solid-angle density of wi; for delta lobes the discrete probability
  float eta = 1.0f;  // for transmission: index of the side wi lies on over that of wo; 1 for reflection
  bool isDelta = false;
  bool valid = false;
};

}  // namespace candela
