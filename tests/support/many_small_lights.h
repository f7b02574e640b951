#pragma once
#include <cstdint>

#include "scene/scene.h"

namespace candela::test {

// A grey floor with a few grey boxes on it under `lights` small emissive squares facing down, at random heights,
// places, sizes and colours (the same seed, the same scene), seen from above at an angle, with no environment: many
// lights, with shadow edges for the reuse between pixels to get wrong.
Scene makeManySmallLights(uint32_t lights, uint32_t seed);

}  // namespace candela::test
