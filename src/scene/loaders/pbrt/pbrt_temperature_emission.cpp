#include "scene/loaders/pbrt/pbrt_temperature_emission.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "scene/loaders/pbrt/pbrt_spectra.h"

namespace candela {

namespace {

// The table's steps: at least 512 an octave, from the cutoff to the hottest temperature evaluated.
const double kOctaves = std::log2(kEmissionMaxKelvin / kEmissionCutoffKelvin);
const size_t kSteps = size_t(std::ceil(kOctaves * 512.0));

// The emission at kEmissionCutoffKelvin x 2^(kOctaves x i / kSteps), i = 0 to kSteps (kEmissionMaxKelvin).
const std::vector<Vec3>& emissionTable() {
  static const std::vector<Vec3> table = [] {
    std::vector<Vec3> t(kSteps + 1);
    for (size_t i = 0; i <= kSteps; ++i)
      t[i] = peakNormalisedBlackbodyRgb(kEmissionCutoffKelvin * std::exp2(kOctaves * double(i) / double(kSteps)));
    return t;
  }();
  return table;
}

}  // namespace

TemperatureToKelvin readTemperatureToKelvin(const PbrtParameters& params) {
  TemperatureToKelvin toKelvin;
  toKelvin.offset = params.getFloat("temperatureoffset", params.getFloat("temperaturecutoff", 0.0f));
  toKelvin.scale = params.getFloat("temperaturescale", 1.0f);
  return toKelvin;
}

Vec3 temperatureEmissionRgb(double kelvin) {
  // NaN falls here too.
  if (!(kelvin > kEmissionCutoffKelvin)) return {0, 0, 0};
  const std::vector<Vec3>& table = emissionTable();
  const double at = std::log2(std::min(kelvin, kEmissionMaxKelvin) / kEmissionCutoffKelvin) / kOctaves * double(kSteps);
  const size_t i = std::min(size_t(at), kSteps - 1);
  const float f = float(std::min(at - double(i), 1.0));
  return table[i] * (1.0f - f) + table[i + 1] * f;
}

}  // namespace candela
