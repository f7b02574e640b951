#pragma once
// Grid media for tests/media, built as the pbrt loader builds them (samples, then the majorant grid).
#include <vector>

#include "kernel/media/medium_grid.h"
#include "scene/medium_grids.h"
#include "scene/scene.h"

namespace candela::test {

// A uniformgrid medium: sigma_a and sigma_s times `density` (nx ny nz samples, x fastest) over the world-space box
// [p0, p1]; its grid and samples are appended to `grids` and `values`.
inline Medium addDensityGrid(std::vector<MediumGrid>& grids, std::vector<float>& values, Vec3 sigmaA, Vec3 sigmaS,
                             uint32_t nx, uint32_t ny, uint32_t nz, const std::vector<float>& density, Vec3 p0,
                             Vec3 p1) {
  Medium m;
  m.sigmaA = sigmaA;
  m.sigmaS = sigmaS;
  MediumGrid grid;
  grid.kind = MediumGridKind::Density;
  grid.p0 = p0;
  grid.p1 = p1;
  grid.nx = nx;
  grid.ny = ny;
  grid.nz = nz;
  grid.density = uint32_t(values.size());
  values.insert(values.end(), density.begin(), density.end());
  buildMajorantGrid(m, grid, values);
  m.grid = uint32_t(grids.size());
  grids.push_back(grid);
  return m;
}

// The same into a scene's media; returns the medium's index.
inline uint32_t addDensityGrid(Scene& scene, Vec3 sigmaA, Vec3 sigmaS, uint32_t nx, uint32_t ny, uint32_t nz,
                               const std::vector<float>& density, Vec3 p0, Vec3 p1) {
  scene.media.push_back(
      addDensityGrid(scene.mediumGrids, scene.mediumGridValues, sigmaA, sigmaS, nx, ny, nz, density, p0, p1));
  return uint32_t(scene.media.size() - 1);
}

}  // namespace candela::test
