#pragma once
// Ken Perlin's improved noise as pbrt-v4 computes it (util/noise.cpp: Noise, DNoise), for the procedural cloud
// medium (cloud_density.h): the same lattice, permutation and fade curve, so that a pbrt scene's cloud has the
// same shape here. Host and device: the permutation is a table in constant memory under nvcc.
#include <cstdint>

#include "core/math.h"

// Perlin's permutation of 0..255 (the one pbrt-v4 and the reference implementation use).
#define CANDELA_NOISE_PERMUTATION                                                                                      \
  151, 160, 137, 91, 90, 15, 131, 13, 201, 95, 96, 53, 194, 233, 7, 225, 140, 36, 103, 30, 69, 142, 8, 99, 37, 240,    \
      21, 10, 23, 190, 6, 148, 247, 120, 234, 75, 0, 26, 197, 62, 94, 252, 219, 203, 117, 35, 11, 32, 57, 177, 33, 88, \
      237, 149, 56, 87, 174, 20, 125, 136, 171, 168, 68, 175, 74, 165, 71, 134, 139, 48, 27, 166, 77, 146, 158, 231,   \
      83, 111, 229, 122, 60, 211, 133, 230, 220, 105, 92, 41, 55, 46, 245, 40, 244, 102, 143, 54, 65, 25, 63, 161, 1,  \
      216, 80, 73, 209, 76, 132, 187, 208, 89, 18, 169, 200, 196, 135, 130, 116, 188, 159, 86, 164, 100, 109, 198,     \
      173, 186, 3, 64, 52, 217, 226, 250, 124, 123, 5, 202, 38, 147, 118, 126, 255, 82, 85, 212, 207, 206, 59, 227,    \
      47, 16, 58, 17, 182, 189, 28, 42, 223, 183, 170, 213, 119, 248, 152, 2, 44, 154, 163, 70, 221, 153, 101, 155,    \
      167, 43, 172, 9, 129, 22, 39, 253, 19, 98, 108, 110, 79, 113, 224, 232, 178, 185, 112, 104, 218, 246, 97, 228,   \
      251, 34, 242, 193, 238, 210, 144, 12, 191, 179, 162, 241, 81, 51, 145, 235, 249, 14, 239, 107, 49, 192, 214, 31, \
      181, 199, 106, 157, 184, 84, 204, 176, 115, 121, 50, 45, 127, 4, 150, 254, 138, 236, 205, 93, 222, 114, 67, 29,  \
      24, 72, 243, 141, 128, 195, 78, 66, 215, 61, 156, 180

namespace candela {

namespace noise_detail {
#if defined(__CUDACC__)
static __constant__ const uint8_t kDevicePermutation[256] = {CANDELA_NOISE_PERMUTATION};
#endif
inline constexpr uint8_t kHostPermutation[256] = {CANDELA_NOISE_PERMUTATION};

CANDELA_FN int permutation(int i) {
#if defined(__CUDA_ARCH__)
  return kDevicePermutation[i & 255];
#else
  return kHostPermutation[i & 255];
#endif
}

// The gradient of lattice point (x, y, z), one of pbrt's 12 edge directions, dotted with the offset (dx, dy, dz).
CANDELA_FN float gradient(int x, int y, int z, float dx, float dy, float dz) {
  const int h = permutation(permutation(permutation(x) + y) + z) & 15;
  const float u = h < 8 || h == 12 || h == 13 ? dx : dy;
  const float v = h < 4 || h == 12 || h == 13 ? dy : dz;
  return ((h & 1) ? -u : u) + ((h & 2) ? -v : v);
}

CANDELA_FN float fade(float t) { return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f); }
}  // namespace noise_detail

// Noise in about [-1, 1], 0 at every lattice point.
CANDELA_FN float perlinNoise(Vec3 p) {
  using namespace noise_detail;
  // Far coordinates wrap, as pbrt's do, so that the integer cell fits.
  const float x = fmodf(p.x, float(1 << 30)), y = fmodf(p.y, float(1 << 30)), z = fmodf(p.z, float(1 << 30));
  const float fx = floorf(x), fy = floorf(y), fz = floorf(z);
  const float dx = x - fx, dy = y - fy, dz = z - fz;
  const int ix = int(fx) & 255, iy = int(fy) & 255, iz = int(fz) & 255;
  const float w000 = gradient(ix, iy, iz, dx, dy, dz);
  const float w100 = gradient(ix + 1, iy, iz, dx - 1, dy, dz);
  const float w010 = gradient(ix, iy + 1, iz, dx, dy - 1, dz);
  const float w110 = gradient(ix + 1, iy + 1, iz, dx - 1, dy - 1, dz);
  const float w001 = gradient(ix, iy, iz + 1, dx, dy, dz - 1);
  const float w101 = gradient(ix + 1, iy, iz + 1, dx - 1, dy, dz - 1);
  const float w011 = gradient(ix, iy + 1, iz + 1, dx, dy - 1, dz - 1);
  const float w111 = gradient(ix + 1, iy + 1, iz + 1, dx - 1, dy - 1, dz - 1);
  const float wx = fade(dx), wy = fade(dy), wz = fade(dz);
  const float y0 = lerp(wy, lerp(wx, w000, w100), lerp(wx, w010, w110));
  const float y1 = lerp(wy, lerp(wx, w001, w101), lerp(wx, w011, w111));
  return lerp(wz, y0, y1);
}

// pbrt's DNoise: the noise's gradient by forward differences of 0.01.
CANDELA_FN Vec3 perlinNoiseGradient(Vec3 p) {
  constexpr float kDelta = 0.01f;
  const float n = perlinNoise(p);
  return Vec3{perlinNoise(p + Vec3{kDelta, 0, 0}) - n, perlinNoise(p + Vec3{0, kDelta, 0}) - n,
              perlinNoise(p + Vec3{0, 0, kDelta}) - n} *
         (1.0f / kDelta);
}

}  // namespace candela
