#include "scene/loaders/pbrt/pbrt_nanovdb_medium.h"

#include "io/load_budget.h"
#include "io/load_diagnostics.h"
#include "scene/loaders/nanovdb/nanovdb_dense_grid.h"
#include "scene/loaders/nanovdb/nanovdb_file.h"

namespace candela {

namespace {

std::string size3(uint64_t x, uint64_t y, uint64_t z) {
  return std::to_string(x) + " x " + std::to_string(y) + " x " + std::to_string(z);
}

}  // namespace

glm::mat4 readPbrtNanoVdbDensity(const std::string& name, const PbrtParameters& params, PbrtContext& context,
                                 MediumGrid& grid, uint32_t maxResolution) {
  const std::string reference = params.getString("filename", "");
  if (reference.empty()) params.fail("nanovdb medium '" + name + "' needs a \"string filename\"");
  const std::string gridName = params.getString("gridname", "density");
  const std::string temperatureName = params.getString("temperaturename", "temperature");
  // Emission from temperature is not rendered: its parameters say nothing else.
  for (const char* unrendered : {"Lescale", "temperaturecutoff", "temperatureoffset", "temperaturescale"})
    if (const PbrtParameter* p = params.find(unrendered)) p->used = true;
  const std::string path = context.resolve(reference, params.file, params.line);
  Scene& scene = context.scene;
  NanoVdbDenseGrid dense;
  try {
    const NanoVdbFile file(path);
    const NanoVdbGridEntry* entry = file.find(gridName);
    if (!entry) {
      std::string names;
      for (const NanoVdbGridEntry& g : file.grids()) names += (names.empty() ? "'" : ", '") + g.name + "'";
      failLoad(path, "has no grid named '" + gridName + "' (its grids: " + names + ")");
    }
    if (entry->valueType != kNanoVdbFloat)
      failLoad(path, "grid '" + gridName + "' holds " + nanoVdbTypeName(entry->valueType) +
                         " values; only float grids are read");
    dense = appendNanoVdbDenseGrid(file.gridBytes(*entry), path, gridName, maxResolution, scene.mediumGridValues);
    if (file.find(temperatureName))
      context.warn("medium temperature",
                   "nanovdb '" + temperatureName + "' grids are not rendered: the medium does not emit");
  } catch (const LoadBudgetError&) {
    throw;
  } catch (const LoadError& e) {
    params.fail(std::string("nanovdb medium '") + name + "': " + e.what());
  }
  const uint64_t majorantRoom = uint64_t(kMajorantGridResolution) * kMajorantGridResolution * kMajorantGridResolution;
  if (scene.mediumGridValues.size() + majorantRoom >= uint64_t(kNoGridValues))
    params.fail("medium '" + name + "': the scene's grids hold more than 2^32 samples");
  if (dense.downsampled) {
    const auto voxels = [&](int a) { return uint64_t(int64_t(dense.indexMax[a]) - dense.indexMin[a] + 1); };
    context.warn("nanovdb resolution " + name,
                 "nanovdb medium '" + name + "': its " + size3(voxels(0), voxels(1), voxels(2)) +
                     " voxels are area-averaged down to " + size3(dense.nx, dense.ny, dense.nz) + " (at most " +
                     std::to_string(maxResolution) + " a side)");
  }
  grid.kind = MediumGridKind::Density;
  grid.nx = dense.nx;
  grid.ny = dense.ny;
  grid.nz = dense.nz;
  grid.density = uint32_t(dense.offset);
  // The voxels' cells: voxel i's centre, where NanoVDB puts its value, is index i.
  grid.p0 = {float(dense.indexMin[0]) - 0.5f, float(dense.indexMin[1]) - 0.5f, float(dense.indexMin[2]) - 0.5f};
  grid.p1 = {float(dense.indexMax[0]) + 0.5f, float(dense.indexMax[1]) + 0.5f, float(dense.indexMax[2]) + 0.5f};
  glm::mat4 mediumFromIndex(1.0f);
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 4; ++col) mediumFromIndex[col][row] = float(dense.worldFromIndex[4 * row + col]);
  return mediumFromIndex;
}

}  // namespace candela
