#pragma once
// A participating medium. Homogeneous (pbrt-v4's HomogeneousMedium): absorption and scattering coefficients per
// unit of world length, per RGB channel, an isotropic emitted radiance and a Henyey-Greenstein asymmetry g. pbrt's
// `scale` is folded into the coefficients and `Lescale` into the emission when a scene is loaded. A medium that
// names a grid (medium_grid.h) is heterogeneous: its coefficients and emission are these times the grid's factors.
#include <cstdint>

#include "core/math.h"

namespace candela {

// A ray, instance side or camera in no medium: vacuum.
constexpr uint32_t kNoMedium = 0xffffffffu;
// A medium that is the same everywhere.
constexpr uint32_t kHomogeneous = 0xffffffffu;

struct Medium {
  Vec3 sigmaA;                   // absorption coefficient
  Vec3 sigmaS;                   // scattering coefficient
  Vec3 emission;                 // radiance emitted per unit of absorption (pbrt-v4: sigma_a x Le is the source term)
  float g = 0.0f;                // Henyey-Greenstein asymmetry in (-1, 1): positive scatters forwards
  uint32_t grid = kHomogeneous;  // or its entry of the scene's mediumGrids
  // 1: the interior of a subsurface material, in which paths take a random walk (kernel/media/subsurface_walk.h).
  uint32_t subsurface = 0;
};

// The media on the two sides of a surface, as pbrt-v4's MediumInterface: `outside` where its geometric normal (as
// wound, kernel/triangle_attributes.h) points, `inside` behind it. Where the two are equal the surface bounds no
// medium, and a ray crossing it stays in the medium it was in.
struct MediumInterface {
  uint32_t inside = kNoMedium;
  uint32_t outside = kNoMedium;
};

CANDELA_FN Vec3 mediumSigmaT(const Medium& m) { return m.sigmaA + m.sigmaS; }

// exp(-sigma_t x distance) per channel: the exact transmittance of a homogeneous medium over `distance` (infinite:
// 0 where sigma_t is positive, 1 where the channel does not interact).
CANDELA_FN Vec3 mediumTransmittance(const Medium& m, float distance) {
  const Vec3 st = mediumSigmaT(m);
  auto channel = [&](float s) { return s > 0.0f ? expf(-s * distance) : 1.0f; };
  return {channel(st.x), channel(st.y), channel(st.z)};
}

}  // namespace candela
