#pragma once

namespace candela {

// A triangle that covers the viewport; `uv` is (0, 0) at the top-left of the image and (1, 1) at its
// bottom-right, matching Image's top-row-first layout in the texture.
inline constexpr const char* kFullViewportVertexShader = R"(#version 330 core
out vec2 uv;
void main() {
  vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  uv = vec2(p.x, 1.0 - p.y);
  gl_Position = vec4(2.0 * p - 1.0, 0.0, 1.0);
}
)";

// The sum of image/filters/bilateral.cpp, texel for texel: the output has the input's layout. With
// `separateEmission`, the part of the image the camera sees emitted (`emission`, Backend::readEmission) is kept out
// of the sum and added back after, as bilateralFilter(input, emission, params) does (bilateralReflected in
// bilateral_kernel.h): an emitter is not smeared over its surroundings, nor they over it.
inline constexpr const char* kBilateralFragmentShader = R"(#version 330 core
uniform sampler2D image;
uniform sampler2D emission;
uniform bool separateEmission;
uniform int radius;
uniform float spatialScale;  // 1 / (2 spatialSigma^2)
uniform float rangeScale;    // 1 / (2 rangeSigma^2)
out vec4 result;
vec3 filtered(ivec2 q) {
  vec3 c = texelFetch(image, q, 0).rgb;
  if (!separateEmission) return c;
  return min(max(c - texelFetch(emission, q, 0).rgb, vec3(0.0)), vec3(1e18));
}
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  ivec2 size = textureSize(image, 0);
  vec3 centre = filtered(p);
  vec3 sum = vec3(0.0);
  float weightSum = 0.0;
  for (int dy = -radius; dy <= radius; ++dy) {
    if (p.y + dy < 0 || p.y + dy >= size.y) continue;
    for (int dx = -radius; dx <= radius; ++dx) {
      if (p.x + dx < 0 || p.x + dx >= size.x) continue;
      vec3 c = filtered(p + ivec2(dx, dy));
      vec3 d = c - centre;
      float weight = exp(-float(dx * dx + dy * dy) * spatialScale - dot(d, d) * rangeScale);
      sum += c * weight;
      weightSum += weight;
    }
  }
  vec3 emitted = separateEmission ? texelFetch(emission, p, 0).rgb : vec3(0.0);
  result = vec4(sum / weightSum + emitted, 1.0);
}
)";

// image/tonemap.h's toneMap: exposure, the tone curve, sRGB encoding. `toneMapper` is a ToneMapper value.
inline constexpr const char* kToneMapFragmentShader = R"(#version 330 core
uniform sampler2D image;
uniform float exposureScale;  // 2^exposure
uniform int toneMapper;  // 0 ACES filmic, 1 clamp, 2 Reinhard
in vec2 uv;
out vec4 colour;
float acesFilmic(float x) {
  const float a = 2.51, b = 0.03, c = 2.43, d = 0.59, e = 0.14;
  return clamp((x * (a * x + b)) / (x * (c * x + d) + e), 0.0, 1.0);
}
float reinhard(float x) {
  x = max(x, 0.0);
  return x / (1.0 + x);
}
float linearToSrgb(float x) {
  x = clamp(x, 0.0, 1.0);
  return x <= 0.0031308 ? 12.92 * x : 1.055 * pow(x, 1.0 / 2.4) - 0.055;
}
void main() {
  vec3 c = texture(image, uv).rgb * exposureScale;
  if (toneMapper == 0) c = vec3(acesFilmic(c.r), acesFilmic(c.g), acesFilmic(c.b));
  if (toneMapper == 2) c = vec3(reinhard(c.r), reinhard(c.g), reinhard(c.b));
  colour = vec4(linearToSrgb(c.r), linearToSrgb(c.g), linearToSrgb(c.b), 1.0);
}
)";

}  // namespace candela
