#pragma once
// Every model of CANDELA_MATERIAL_MODELS (kernel/material.h), and what the model of a material's type says about
// the material before a Bsdf is built. A mix has no model of its own: it scatters as the material it chooses.
// Each question is a chain `type == A && A's answer || type == B && B's answer || ...`, in which the models'
// constant answers fold away: `type == Mirror || type == Glass` for isDeltaModel, as written by hand.
#include "kernel/bsdf/blinn_phong.h"
#include "kernel/bsdf/diffuse_transmission.h"
#include "kernel/bsdf/disney.h"
#include "kernel/bsdf/hair.h"
#include "kernel/bsdf/lambertian.h"
#include "kernel/bsdf/pbr.h"
#include "kernel/bsdf/specular.h"
#include "kernel/material.h"

namespace candela {

// Whether the model of `type` has only delta lobes (mirror, smooth glass).
CANDELA_FN constexpr bool isDeltaModel(MaterialType type) {
#define CANDELA_DELTA_TERM(t, Model, name, shadingName) || (Model::kDelta && type == MaterialType::t)
  return false CANDELA_MATERIAL_MODELS(CANDELA_DELTA_TERM);
#undef CANDELA_DELTA_TERM
}

// Whether a surface of `m` can let light through to its other side (Model::transmits).
CANDELA_FN bool isTransmissive(const Material& m) {
#define CANDELA_TRANSMITS_TERM(t, Model, name, shadingName) || (m.type == MaterialType::t && Model::transmits(m))
  return false CANDELA_MATERIAL_MODELS(CANDELA_TRANSMITS_TERM);
#undef CANDELA_TRANSMITS_TERM
}

// Whether the lobes of `m` turn with the surface's tangent (Model::orientedByTangent).
CANDELA_FN bool isOrientedByTangent(const Material& m) {
#define CANDELA_TANGENT_TERM(t, Model, name, shadingName) || (m.type == MaterialType::t && Model::orientedByTangent(m))
  return false CANDELA_MATERIAL_MODELS(CANDELA_TANGENT_TERM);
#undef CANDELA_TANGENT_TERM
}

}  // namespace candela
