#include "scene/loaders/pbrt/pbrt_temperature_emission.h"

#include <algorithm>
#include <cmath>

#include "io/load_budget.h"
#include "kernel/media/medium_grid.h"
#include "scene/loaders/pbrt/pbrt_grid_media.h"
#include "scene/loaders/pbrt/pbrt_spectra.h"

namespace candela {

TemperatureToKelvin readTemperatureToKelvin(const PbrtParameters& params) {
  TemperatureToKelvin toKelvin;
  toKelvin.offset = params.getFloat("temperatureoffset", params.getFloat("temperaturecutoff", 0.0f));
  toKelvin.scale = params.getFloat("temperaturescale", 1.0f);
  if (!std::isfinite(toKelvin.offset) || !std::isfinite(toKelvin.scale))
    params.fail("medium: 'temperatureoffset', 'temperaturecutoff' and 'temperaturescale' must be finite");
  return toKelvin;
}

namespace {

double blackbodyTableKelvin(uint32_t i) {
  return double(kBlackbodyCutoffKelvin) * std::exp2(double(i) / kBlackbodyStepsPerOctave);
}

}  // namespace

Vec3 blackbodyTableEntry(uint32_t i) { return peakNormalisedBlackbodyRgb(blackbodyTableKelvin(i)); }

bool emitFromTemperature(const PbrtParameters& params, const std::string& name, uint32_t offset,
                         const TemperatureToKelvin& toKelvin, MediumGrid& grid, Scene& scene) {
  std::vector<float>& values = scene.mediumGridValues;
  auto emits = [&](float t) { return toKelvin(t) > double(kBlackbodyCutoffKelvin); };
  if (!emits(0.0f) && std::none_of(values.begin() + offset, values.end(), emits)) {
    releaseLoadMemory((values.size() - offset) * sizeof(float));
    values.resize(offset);
    return false;
  }
  grid.temperature = offset;
  grid.temperatureOffset = toKelvin.offset;
  grid.temperatureScale = toKelvin.scale;
  for (const MediumGrid& other : scene.mediumGrids)
    if (other.blackbody != kNoGridValues) {
      grid.blackbody = other.blackbody;
      return true;
    }
  checkGridValuesRoom(params, name, values.size() + 3 * uint64_t(kBlackbodyTableSize));
  grid.blackbody = uint32_t(values.size());
  std::vector<double> kelvins(kBlackbodyTableSize);
  for (uint32_t i = 0; i < kBlackbodyTableSize; ++i) kelvins[i] = blackbodyTableKelvin(i);
  for (const Vec3& rgb : peakNormalisedBlackbodyRgbs(kelvins)) values.insert(values.end(), {rgb.x, rgb.y, rgb.z});
  return true;
}

}  // namespace candela
