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

// A BSDF's value and density for one pair of directions, computed together (as Mitsuba 3's eval_pdf, Falcor's
// evalPdf): next-event estimation needs both, for the contribution and its MIS weight, and so does a mixture
// sample. Each model's evalPdf() shares the work its separate eval() and pdf() would each do, and returns the
// same numbers.
struct BsdfEval {
  Vec3 f;
  float pdf = 0.0f;
};

}  // namespace candela
