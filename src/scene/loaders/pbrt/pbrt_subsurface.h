#pragma once
#include "kernel/media/medium.h"
#include "scene/loaders/pbrt/pbrt_context.h"
#include "scene/loaders/pbrt/pbrt_parameters.h"
#include "scene/loaders/pbrt/pbrt_textures.h"

namespace candela {

// The medium inside a pbrt-v4 `subsurface` material, in which candela's random walk runs (where pbrt-v4 uses a
// tabulated BSSRDF). pbrt's four exclusive forms: a measured preset (`name`, whose g is 0), `sigma_a` with
// `sigma_s`, `reflectance` with `mfp` (default 1; the reflectance is the walk's multiple-scattering albedo,
// subsurface_albedo.h), or neither (pbrt's defaults, whole milk per millimetre). `scale` multiplies the
// coefficients, or the mean free path; `g` is the phase function's asymmetry. A textured parameter takes its mean
// colour, with a warning. Parameters that are not finite, negative coefficients or mean free paths, a `scale` or
// `mfp` of 0 and |g| >= 1 are refused with one line naming the file.
Medium pbrtSubsurfaceInterior(const PbrtParameters& params, PbrtTextures& textures, PbrtContext& context);

}  // namespace candela
