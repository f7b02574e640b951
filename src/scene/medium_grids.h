#pragma once
// The host side of grid media (kernel/media/medium_grid.h): their majorant grids, built once when a scene is
// loaded, and the checks that a grid read from a file or the scene cache names only samples that exist.
#include <cstddef>
#include <string>
#include <vector>

#include "kernel/media/medium_grid.h"

namespace candela {

// Appends the majorant grid of `grid` (the grid of medium m, whose samples are already in `values`) to `values`
// and records it in `grid`: pbrt-v4's 16^3 voxels over the box for uniformgrid and rgbgrid, each the largest
// sigma_t of any channel at the samples that its trilinear lookups reach (the lookup is a convex combination of
// them); one voxel for the cloud, whose density never exceeds 1.
void buildMajorantGrid(const Medium& m, MediumGrid& grid, std::vector<float>& values);

// What is wrong with `grid` in a scene whose grid samples are `values`, or "" where nothing is: a kind, size,
// offset or box out of range, a non-finite transform, cloud or temperature parameter, or a negative sample among
// those it names other than its temperatures. That every sample is finite is mediumGridValuesProblem's check.
std::string mediumGridProblem(const MediumGrid& grid, const std::vector<float>& values);
// Whether the samples are all finite ("" where they are).
std::string mediumGridValuesProblem(const std::vector<float>& values);

}  // namespace candela
