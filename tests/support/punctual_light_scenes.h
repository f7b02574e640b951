#pragma once
// Scenes lit by punctual lights whose answers are known exactly.
#include <cstdint>
#include <optional>

#include "scene/scene.h"

namespace candela::test {

// A point light of intensity I at the centre of a closed diffuse sphere of radius 1 and albedo a, seen from the
// centre. Direct light gives every point of the wall irradiance I, and the wall then radiates uniformly: as in
// the emissive sphere, L = (a / pi) (I + pi L), so every pixel sees L = a I / (pi (1 - a)). The sphere is
// tessellated finely (flat facets within 2e-4 of the unit sphere) so that the facets' varying distance from
// the light moves the answer by less than 1e-3.
Scene makePointLitSphere(float albedo, float intensity);
inline float pointLitSphereRadiance(float albedo, float intensity) {
  return albedo * intensity / (kPi * (1.0f - albedo));
}

// A large diffuse floor of albedo a under a directional light of irradiance E arriving at `cosAngle` from the
// floor's normal, seen from above: nothing else reflects, so every pixel sees L = a E cosAngle / pi exactly.
Scene makeDirectionallyLitFloor(float albedo, float irradiance, float cosAngle);
inline float directionallyLitFloorRadiance(float albedo, float irradiance, float cosAngle) {
  return albedo * irradiance * cosAngle / kPi;
}

// That floor made of a mix of two greys: `second` at each shading point with probability `amount`, else `first`
// (pbrt-v4's convention), so that every pixel sees the floor of albedo (1 - amount) first + amount second. With
// `amountTexel`, the amount is `amount` times a one-texel linear texture of that byte value. Materials 0 and 1
// are the greys; the floor's two triangles use the mix, material 2.
Scene makeMixedFloor(float first, float second, float amount, std::optional<uint8_t> amountTexel, float irradiance,
                     float cosAngle);

}  // namespace candela::test
