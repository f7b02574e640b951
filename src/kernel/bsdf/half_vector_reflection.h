#pragma once
#include "kernel/bsdf/bsdf_sample.h"
#include "kernel/bsdf/fresnel.h"

namespace candela {

// Completes a reflection lobe's sample from the half vector it drew: wi is wo mirrored about h, and value and
// density come from the lobe's own evalPdf(), so the three always agree.
template <class Lobe>
CANDELA_FN BsdfSample reflectAboutHalfVector(const Lobe& lobe, Vec3 wo, Vec3 h) {
  BsdfSample s;
  if (dot(wo, h) <= 0.0f) return s;
  s.wi = reflect(wo, h);
  if (s.wi.z <= 0.0f) return s;
  BsdfEval e = lobe.evalPdf(wo, s.wi);
  s.f = e.f;
  s.pdf = e.pdf;
  s.valid = s.pdf > 0.0f;
  return s;
}

}  // namespace candela
