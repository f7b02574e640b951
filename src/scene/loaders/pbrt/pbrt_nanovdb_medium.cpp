#include "scene/loaders/pbrt/pbrt_nanovdb_medium.h"

#include <cmath>
#include <optional>

#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <glm/vec3.hpp>

#include "io/load_budget.h"
#include "io/load_diagnostics.h"
#include "scene/loaders/nanovdb/nanovdb_dense_grid.h"
#include "scene/loaders/nanovdb/nanovdb_file.h"
#include "scene/loaders/pbrt/pbrt_grid_media.h"
#include "scene/loaders/pbrt/pbrt_temperature_emission.h"

namespace candela {

namespace {

std::string size3(uint64_t x, uint64_t y, uint64_t z) {
  return std::to_string(x) + " x " + std::to_string(y) + " x " + std::to_string(z);
}

// The file's grids' names, quoted, for messages.
std::string gridNames(const NanoVdbFile& file) {
  std::string names;
  for (const NanoVdbGridEntry& g : file.grids()) names += (names.empty() ? "'" : ", '") + g.name + "'";
  return names;
}

// Whether the index-to-world map `other` puts every voxel of `dense`'s index box within a hundredth of a voxel of
// where `dense`'s own map puts it (checked at the box's corners: the maps are affine).
bool sameVoxels(const NanoVdbDenseGrid& dense, const double (&other)[12]) {
  const auto linear = [](const double(&m)[12]) {
    return glm::dmat3(m[0], m[4], m[8], m[1], m[5], m[9], m[2], m[6], m[10]);  // column by column
  };
  const auto translation = [](const double(&m)[12]) { return glm::dvec3(m[3], m[7], m[11]); };
  const glm::dmat3 otherLinear = linear(other);
  const double det = glm::determinant(otherLinear);
  if (!(std::fabs(det) > 0.0) || !std::isfinite(det)) return false;
  const glm::dmat3 otherInverse = glm::inverse(otherLinear);
  for (int corner = 0; corner < 8; ++corner) {
    const glm::dvec3 index((corner & 1) ? dense.indexMax[0] : dense.indexMin[0],
                           (corner & 2) ? dense.indexMax[1] : dense.indexMin[1],
                           (corner & 4) ? dense.indexMax[2] : dense.indexMin[2]);
    const glm::dvec3 world = linear(dense.worldFromIndex) * index + translation(dense.worldFromIndex);
    const glm::dvec3 there = otherInverse * (world - translation(other));
    for (int a = 0; a < 3; ++a)
      if (!(std::fabs(there[a] - index[a]) <= 0.01)) return false;
  }
  return true;
}

}  // namespace

glm::mat4 readPbrtNanoVdbGrids(const std::string& name, const PbrtParameters& params, PbrtContext& context, Medium& m,
                               MediumGrid& grid, uint32_t maxResolution) {
  const std::string reference = params.getString("filename", "");
  if (reference.empty()) params.fail("nanovdb medium '" + name + "' needs a \"string filename\"");
  const std::string gridName = params.getString("gridname", "density");
  const std::string temperatureName = params.getString("temperaturename", "temperature");
  const float leScale = params.getFloat("Lescale", 1.0f);
  if (leScale < 0.0f) params.fail("nanovdb medium '" + name + "': 'Lescale' must not be negative");
  const TemperatureToKelvin toKelvin = readTemperatureToKelvin(params);
  const std::string path = context.resolve(reference, params.file, params.line);
  Scene& scene = context.scene;
  NanoVdbDenseGrid dense;
  std::optional<uint32_t> temperatures;  // where the temperatures, one per dense sample, begin in the scene's values
  try {
    const NanoVdbFile file(path);
    const NanoVdbGridEntry* entry = file.find(gridName);
    if (!entry) failLoad(path, "has no grid named '" + gridName + "' (its grids: " + gridNames(file) + ")");
    if (entry->valueType != kNanoVdbFloat)
      failLoad(path, "grid '" + gridName + "' holds " + nanoVdbTypeName(entry->valueType) +
                         " values; only float grids are read");
    dense = appendNanoVdbDenseGrid(file.gridBytes(*entry), path, gridName, maxResolution, scene.mediumGridValues);
    // As pbrt-v4, a file without the temperature grid, or `Lescale` 0, makes a medium that does not emit; a name
    // the scene gave itself that the file lacks is most likely a mistake, so it is reported.
    const NanoVdbGridEntry* temperature = file.find(temperatureName);
    if (!temperature && params.find("temperaturename"))
      context.warn("nanovdb temperature " + name, "nanovdb medium '" + name + "': " + path + " has no grid named '" +
                                                      temperatureName + "' (its grids: " + gridNames(file) +
                                                      "): the medium does not emit");
    if (temperature && leScale > 0.0f) {
      if (temperature->valueType != kNanoVdbFloat)
        failLoad(path, "grid '" + temperatureName + "' holds " + nanoVdbTypeName(temperature->valueType) +
                           " values; only float temperatures are read");
      const NanoVdbDenseGrid sampled = appendNanoVdbDenseGridLike(file.gridBytes(*temperature), path, temperatureName,
                                                                  dense, NanoVdbValues::Finite, scene.mediumGridValues);
      temperatures = uint32_t(sampled.offset);
      // Both grids are read over the density's index box, which takes the temperature's voxels to where its own
      // map puts them only where the two maps agree.
      if (!sameVoxels(dense, sampled.worldFromIndex)) {
        context.warn(
            "nanovdb temperature " + name,
            "nanovdb medium '" + name + "': its grids '" + gridName + "' and '" + temperatureName +
                "' have different index-to-world maps (a temperature is read only under its density's map): the "
                "medium does not emit");
        releaseLoadMemory((scene.mediumGridValues.size() - sampled.offset) * sizeof(float));
        scene.mediumGridValues.resize(sampled.offset);
        temperatures.reset();
      }
    }
  } catch (const LoadBudgetError&) {
    throw;
  } catch (const LoadError& e) {
    params.fail(std::string("nanovdb medium '") + name + "': " + e.what());
  }
  checkGridValuesRoom(params, name, scene.mediumGridValues.size());
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
  // A medium whose temperatures cannot exceed the cutoff keeps 1 float a sample.
  if (temperatures && emitFromTemperature(params, name, *temperatures, toKelvin, grid, scene))
    m.emission = Vec3{leScale, leScale, leScale};
  // The voxels' cells: voxel i's centre, where NanoVDB puts its value, is index i.
  grid.p0 = {float(dense.indexMin[0]) - 0.5f, float(dense.indexMin[1]) - 0.5f, float(dense.indexMin[2]) - 0.5f};
  grid.p1 = {float(dense.indexMax[0]) + 0.5f, float(dense.indexMax[1]) + 0.5f, float(dense.indexMax[2]) + 0.5f};
  glm::mat4 mediumFromIndex(1.0f);
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 4; ++col) mediumFromIndex[col][row] = float(dense.worldFromIndex[4 * row + col]);
  return mediumFromIndex;
}

}  // namespace candela
