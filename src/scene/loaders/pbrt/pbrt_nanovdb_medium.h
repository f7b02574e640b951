#pragma once
#include <string>

#include <glm/mat4x4.hpp>

#include "kernel/media/medium_grid.h"
#include "scene/loaders/pbrt/pbrt_context.h"
#include "scene/loaders/pbrt/pbrt_parameters.h"

namespace candela {

// The most samples a side of the dense grid a `nanovdb` medium becomes; larger grids are area-averaged down.
constexpr uint32_t kNanoVdbMaxResolution = 256;

// The density of pbrt-v4's `nanovdb` medium `name`: the float grid `gridname` ("density") of the .nvdb file
// `filename` (resolved and confined as the scene's other files), its voxels as a dense uniformgrid-like grid
// (loaders/nanovdb/nanovdb_dense_grid.h) whose box is the voxels' cells in NanoVDB's index space. Fills `grid`'s
// kind, size, samples (appended to the scene's, charged to the load's budget) and box; returns the medium-from-
// index transform (NanoVDB's index-to-world map). A `temperature` grid in the file is not rendered: one warning.
// Throws LoadError at the directive for a file that cannot be read as such a grid.
glm::mat4 readPbrtNanoVdbDensity(const std::string& name, const PbrtParameters& params, PbrtContext& context,
                                 MediumGrid& grid, uint32_t maxResolution = kNanoVdbMaxResolution);

}  // namespace candela
