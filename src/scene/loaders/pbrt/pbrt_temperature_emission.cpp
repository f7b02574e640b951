#include "scene/loaders/pbrt/pbrt_temperature_emission.h"

#include <algorithm>
#include <cmath>

#include "kernel/media/medium_grid.h"
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

bool temperaturesEmit(const std::vector<float>& temperatures, const TemperatureToKelvin& toKelvin) {
  auto emits = [&](float t) { return toKelvin(t) > double(kBlackbodyCutoffKelvin); };
  return emits(0.0f) || std::any_of(temperatures.begin(), temperatures.end(), emits);
}

Vec3 blackbodyTableEntry(uint32_t i) {
  return peakNormalisedBlackbodyRgb(double(kBlackbodyCutoffKelvin) * std::exp2(double(i) / kBlackbodyStepsPerOctave));
}

void emitFromTemperature(uint32_t offset, const TemperatureToKelvin& toKelvin, MediumGrid& grid, Scene& scene) {
  grid.temperature = offset;
  grid.temperatureOffset = toKelvin.offset;
  grid.temperatureScale = toKelvin.scale;
  for (const MediumGrid& other : scene.mediumGrids)
    if (other.blackbody != kNoGridValues) {
      grid.blackbody = other.blackbody;
      return;
    }
  grid.blackbody = uint32_t(scene.mediumGridValues.size());
  for (uint32_t i = 0; i < kBlackbodyTableSize; ++i) {
    const Vec3 rgb = blackbodyTableEntry(i);
    scene.mediumGridValues.insert(scene.mediumGridValues.end(), {rgb.x, rgb.y, rgb.z});
  }
}

}  // namespace candela
