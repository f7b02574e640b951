#pragma once
#include <string>

#include <glm/mat4x4.hpp>

#include "kernel/media/medium.h"
#include "scene/loaders/pbrt/pbrt_context.h"
#include "scene/loaders/pbrt/pbrt_parameters.h"

namespace candela {

// pbrt-v4's heterogeneous media, `uniformgrid`, `rgbgrid`, `cloud` and `nanovdb` (MakeNamedMedium `type`), with
// pbrt's parameter names and defaults: their grid (kernel/media/medium_grid.h) and its samples go into the scene,
// charged to the load's memory budget, with the majorant grid built; the returned Medium names the grid.
// `worldFromMedium` is the transform in effect at MakeNamedMedium. A nanovdb medium's density and emission are its
// file's grids as dense grids (pbrt_nanovdb_medium.h). Throws LoadError (one line, at the directive) for a grid whose
// size disagrees with its data, absurd sizes, a negative or non-finite sample or parameter, an empty box, or a
// density too high to track (an optical depth above 1e6 across the box). A uniformgrid's `temperature` grid emits
// as pbrt-v4's GridMedium's does (pbrt_temperature_emission.h).
// Refuses, in one line naming medium `name`, a scene whose grids would hold `values` samples and leave no room for
// one more majorant grid within 32-bit offsets.
void checkGridValuesRoom(const PbrtParameters& params, const std::string& name, uint64_t values);

Medium readPbrtGridMedium(const std::string& type, const std::string& name, const PbrtParameters& params,
                          const glm::mat4& worldFromMedium, PbrtContext& context);

// Whether MakeNamedMedium `type` is one of those.
bool isPbrtGridMedium(const std::string& type);

}  // namespace candela
