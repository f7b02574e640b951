#pragma once
#include "kernel/bsdf/bsdf_sample.h"
#include "kernel/bsdf/fresnel.h"

namespace candela {

// Completes a reflection lobe's sample from the half vector it drew: wi is wo mirrored about h, and value and
// density come from the lobe's own eval() and pdf(), so the three always agree.
template <class Lobe>
CANDELA_FN BsdfSample reflectAboutHalfVector(const Lobe& lobe, Vec3 wo, Vec3 h) {
  BsdfSample s;
  if (dot(wo, h) <= 0.0f) return s;
  s.wi = reflect(wo, h);
  if (s.wi.z <= 0.0f) return s;
  s.pdf = lobe.pdf(wo, s.wi);
  s.f = lobe.eval(wo, s.wi);
  s.valid = s.pdf > 0.0f;
  return s;
}

}  // namespace candela
