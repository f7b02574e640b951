#pragma once
#include <optional>
#include <string>

#include "core/math.h"

namespace candela {

// Measured scattering coefficients of a named material, per millimetre, in RGB (pbrt-v4's
// GetMediumScatteringProperties): sigma_s is the reduced scattering coefficient sigma_s (1 - g), so the medium
// they describe scatters isotropically.
struct ScatteringPreset {
  Vec3 sigmaA;
  Vec3 sigmaS;
};

// The preset pbrt-v4 calls `name` ("Skin1", "Ketchup", "Wholemilk", ...), matched exactly; nothing for another
// name.
std::optional<ScatteringPreset> pbrtScatteringPreset(const std::string& name);

}  // namespace candela
