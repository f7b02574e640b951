#pragma once
#include "kernel/bsdf/material_models.h"
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

CANDELA_FN bool isSpecularMaterial(const Material& m) { return isDeltaModel(m.type); }

}  // namespace candela
