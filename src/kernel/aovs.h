#pragma once
#include "kernel/bsdf/material_models.h"
#include "kernel/kernel_variant.h"
#include "kernel/material.h"

namespace candela {

// What a path saw at its first non-specular vertex, where it followed mirrors and smooth glass from the camera
// up to there: the guides of the denoisers. Averaged over a pixel's samples like colour.
struct PathAovs {
  // The vertex's reflectance (materialAlbedo) times the weight of the specular chain before it; where the path
  // escaped, the chain's weight alone (the environment is treated as white).
  Vec3 albedo;
  Vec3 normal;         // shading normal, world space, turned towards the arriving path; zero where it escaped
  float depth = 0.0f;  // length of the path from the camera to the vertex; zero where it escaped
};

// A material's reflectance for the albedo guide: the colour its lobes scale light by at normal incidence,
// clamped to [0, 1]; for hair, the colour its absorption gives (HairBsdf::reflectanceOfAbsorption). Delta
// materials never reach it (the AOVs follow them).
CANDELA_FN Vec3 materialAlbedo(const Material& m) {
  Vec3 a = kernelHasModel(MaterialType::Hair) && m.type == MaterialType::Hair
               ? HairBsdf::reflectanceOfAbsorption(m.fibreAbsorption, m.azimuthalRoughness)
               : m.baseColor;
  if (m.type == MaterialType::BlinnPhong) a += m.specularColor;
  if (m.type == MaterialType::DiffuseTransmission) a += m.transmittance;
  return {clampf(a.x, 0.0f, 1.0f), clampf(a.y, 0.0f, 1.0f), clampf(a.z, 0.0f, 1.0f)};
}

CANDELA_FN bool isSpecularMaterial(const Material& m) { return isDeltaModel(m.type); }

}  // namespace candela
