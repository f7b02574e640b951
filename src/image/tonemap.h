#pragma once
#include <cstdint>

#include "core/math.h"

namespace candela {

// How linear radiance (after exposure) becomes display values in [0, 1] before sRGB encoding. The viewer's
// GLSL (app/viewer/display_shaders.h) mirrors this file; its values are the shader's `toneMapper` uniform.
enum class ToneMapper {
  AcesFilmic = 0,  // Narkowicz's fit of the ACES filmic curve
  Clamp = 1,       // linear, clamped to [0, 1]
  Reinhard = 2,    // x / (1 + x) per channel
};

// Narkowicz's fit of the ACES filmic curve before its clamp to [0, 1] (image/display_kernel.h clamps it its own way).
CANDELA_FN float acesFilmicUnclamped(float x) {
  constexpr float a = 2.51f, b = 0.03f, c = 2.43f, d = 0.59f, e = 0.14f;
  return (x * (a * x + b)) / (x * (c * x + d) + e);
}

// Narkowicz's fit of the ACES filmic curve, applied per channel.
CANDELA_FN float acesFilmic(float x) { return clampf(acesFilmicUnclamped(x), 0.0f, 1.0f); }

CANDELA_FN float reinhard(float x) {
  x = fmaxf(x, 0.0f);
  return x / (1.0f + x);
}

CANDELA_FN float linearToSrgb(float x) {
  x = clampf(x, 0.0f, 1.0f);
  return x <= 0.0031308f ? 12.92f * x : 1.055f * powf(x, 1.0f / 2.4f) - 0.055f;
}

// Linear radiance to display-referred sRGB in [0, 1]. `exposure` is in stops.
CANDELA_FN Vec3 toneMap(Vec3 radiance, float exposure, ToneMapper mapper) {
  Vec3 c = radiance * exp2f(exposure);
  if (mapper == ToneMapper::AcesFilmic) c = {acesFilmic(c.x), acesFilmic(c.y), acesFilmic(c.z)};
  if (mapper == ToneMapper::Reinhard) c = {reinhard(c.x), reinhard(c.y), reinhard(c.z)};
  return {linearToSrgb(c.x), linearToSrgb(c.y), linearToSrgb(c.z)};
}

// A toneMap channel in [0, 1] as the byte an 8-bit image stores.
CANDELA_FN uint8_t displayByte(float channel) { return uint8_t(channel * 255.0f + 0.5f); }

}  // namespace candela
