#pragma once
// The single-scattering albedo of a medium whose multiple scattering gives a wanted colour: how a subsurface
// material given as a reflectance and a mean free path (pbrt-v4's `reflectance` + `mfp`, Cycles' colour + radius)
// becomes the coefficients of the medium its random walk runs in.
#include "core/math.h"
#include "kernel/media/medium.h"

namespace candela {

// The single-scattering albedo sigma_s / sigma_t of a half-space of Henyey-Greenstein asymmetry g (|g| < 1) whose
// total diffuse reflectance is `albedo` in [0, 1]: light arriving cosine-distributed across an index-matched
// boundary, every order of scattering counted. The fit is Cycles' for its random walk (d'Eon, "A Hitchhiker's
// Guide to Multiple Scattering", eq. 53.7, with van de Hulst's similarity relation for g), clamped below 1.
float singleScatteringAlbedo(float albedo, float g);

// The interior of a subsurface material of diffuse reflectance `reflectance` and mean free path `meanFreePath`
// (per channel, in world units, positive): sigma_t = 1 / meanFreePath, sigma_s = albedo x sigma_t.
Medium subsurfaceMediumFromReflectance(Vec3 reflectance, Vec3 meanFreePath, float g);

}  // namespace candela
