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
#include "kernel/kernel_variant.h"
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

// Whether the GPU's lean kernel (kernel/kernel_variant.h) has the model of `type` (Model::kInLeanKernel): the
// three shading models the viewers switch between, diffuse, mirror and glass, and a mix, which resolves to one of
// its materials before a model is built.
CANDELA_FN constexpr bool isLeanKernelModel(MaterialType type) {
#define CANDELA_LEAN_TERM(t, Model, name, shadingName) || (Model::kInLeanKernel && type == MaterialType::t)
  return type == MaterialType::Mix CANDELA_MATERIAL_MODELS(CANDELA_LEAN_TERM);
#undef CANDELA_LEAN_TERM
}

// Whether this compile of the kernel has the model of `type`.
CANDELA_FN constexpr bool kernelHasModel(MaterialType type) { return !kLeanKernel || isLeanKernelModel(type); }

// Whether the lean kernel renders `m` as the full kernel does: its model is there, and it has no thin film.
CANDELA_FN bool leanKernelRenders(const Material& m) { return isLeanKernelModel(m.type) && !(m.iridescence > 0.0f); }

// A material's reflectance for the denoisers' albedo guide (Model::guideAlbedo: the colour its lobes scale light by
// at normal incidence), clamped to [0, 1]. Delta materials never reach it (the guides follow them); a model this
// compile of the kernel leaves out gives its base colour, as the fallback model it renders with.
CANDELA_FN Vec3 materialAlbedo(const Material& m) {
  Vec3 a = m.baseColor;
#define CANDELA_ALBEDO_CASE(t, Model, name, shadingName) \
  if (kernelHasModel(MaterialType::t) && m.type == MaterialType::t) a = Model::guideAlbedo(m);
  CANDELA_MATERIAL_MODELS(CANDELA_ALBEDO_CASE)
#undef CANDELA_ALBEDO_CASE
  return {clampf(a.x, 0.0f, 1.0f), clampf(a.y, 0.0f, 1.0f), clampf(a.z, 0.0f, 1.0f)};
}

}  // namespace candela
