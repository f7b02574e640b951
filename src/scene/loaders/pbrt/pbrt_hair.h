#pragma once
#include "kernel/material.h"
#include "scene/loaders/pbrt/pbrt_context.h"
#include "scene/loaders/pbrt/pbrt_parameters.h"
#include "scene/loaders/pbrt/pbrt_textures.h"

namespace candela {

// A pbrt-v4 `hair` material as candela's hair model (kernel/bsdf/hair.h). Its absorption comes from the first of
// pbrt's forms given: `sigma_a`; `reflectance` (or `color`), converted as pbrt-v4's SigmaAFromReflectance does for
// the azimuthal roughness; the melanin concentrations `eumelanin` and `pheomelanin`; or pbrt's default, eumelanin
// 1.3. The others are ignored with a warning, as pbrt-v4 does. `eta` (1.55), `beta_m` and `beta_n` (0.3) and
// `alpha` (2 degrees) follow. A textured parameter takes its mean, with a warning. A negative or non-finite
// absorption, reflectance or concentration, a roughness outside (0, 1], an `eta` that is not positive and a
// non-finite `alpha` are refused with one line naming the file.
Material pbrtHairMaterial(const PbrtParameters& params, PbrtTextures& textures, PbrtContext& context);

}  // namespace candela
