#pragma once
#include <string>

#include <glm/mat4x4.hpp>

#include "kernel/media/medium.h"
#include "kernel/media/medium_grid.h"
#include "scene/loaders/pbrt/pbrt_context.h"
#include "scene/loaders/pbrt/pbrt_parameters.h"

namespace candela {

// The most samples a side of the dense grid a `nanovdb` medium becomes; larger grids are area-averaged down.
constexpr uint32_t kNanoVdbMaxResolution = 256;

// pbrt-v4's `nanovdb` medium `name`: the float grid `gridname` ("density") of the .nvdb file `filename` (resolved
// and confined as the scene's other files), its voxels as a dense uniformgrid-like grid (loaders/nanovdb/
// nanovdb_dense_grid.h) whose box is the voxels' cells in NanoVDB's index space, and its emission from the float
// grid `temperaturename` ("temperature") where the file has one (pbrt_temperature_emission.h: `Lescale`,
// `temperatureoffset` or `temperaturecutoff`, `temperaturescale`), sampled over the density's cells. Fills `grid`'s
// kind, size, samples (appended to the scene's, charged to the load's budget) and box, and m's emission where the
// medium emits; returns the medium-from-index transform (NanoVDB's index-to-world map). A medium that emits keeps its
// density grid and adds the temperatures (one float a sample), m's emission `Lescale`. Throws LoadError at the
// directive for a file that cannot be read as such grids.
glm::mat4 readPbrtNanoVdbGrids(const std::string& name, const PbrtParameters& params, PbrtContext& context, Medium& m,
                               MediumGrid& grid, uint32_t maxResolution = kNanoVdbMaxResolution);

}  // namespace candela
