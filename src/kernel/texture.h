#pragma once
#include <cstdint>

#include "core/math.h"

namespace candela {

enum class TextureWrap : uint32_t { Repeat = 0, Clamp, Mirror };
enum class TexelFormat : uint32_t { Unorm8 = 0, Float32 };

// One texture as kernel code sees it. On the host its texels sit in the SceneView's shared texel arrays from
// `offset` on (row 0 first, `channels` values per texel): level 0 of its mip pyramid, then each coarser level
// (mipLevelWidth/Height) right after the one before. A GPU backend may instead create a CUDA texture object
// (normalised coordinates, linear filtering, the same address modes, sRGB reads for `srgb`, four channels, the
// same levels) and store its handle in `deviceTexture`; device code then samples through the texture unit, which
// uses the same texel centres and row order but holds the bilinear weights in 8 fractional bits: its results
// differ from the lookup below by up to 2^-7 of the four texels' spread, plus, for 8-bit formats, one step of the
// 8-bit input as decoded (1/255, or the sRGB curve's step at the brightest texel)
// (tests/gpu/texture_lookup_gpu_test.cpp). Filtered lookups across levels are in kernel/texture_filtering.h.
struct TextureView {
  uint64_t deviceTexture = 0;  // cudaTextureObject_t, 0 when absent
  uint64_t offset = 0;         // first element in SceneView::texelBytes or texelFloats
  uint32_t width = 0;
  uint32_t height = 0;
  uint32_t channels = 4;
  TexelFormat format = TexelFormat::Unorm8;
  uint32_t srgb = 0;                        // 8-bit colour channels encode sRGB; alpha is always linear
  TextureWrap wrapU = TextureWrap::Repeat;  // across the columns (glTF wrapS)
  TextureWrap wrapV = TextureWrap::Repeat;  // down the rows (glTF wrapT)
  uint32_t levels = 1;                      // mip levels stored, level 0 the finest (1: no pyramid)
};

// Level `level`'s side for a level-0 side of `size`: halved and rounded down per level, never below 1 (the
// convention of OpenGL and of CUDA mipmapped arrays).
CANDELA_FN uint32_t mipLevelSize(uint32_t size, uint32_t level) {
  uint32_t s = level >= 32 ? 0u : size >> level;
  return s > 0 ? s : 1u;
}

// How many levels a full pyramid of a width x height texture has: down to 1 x 1.
CANDELA_FN uint32_t fullMipLevelCount(uint32_t width, uint32_t height) {
  uint32_t side = width > height ? width : height, levels = 1;
  while (side > 1) {
    side >>= 1;
    ++levels;
  }
  return levels;
}

// Where level `level`'s texels start, counted in elements from the texture's offset.
CANDELA_FN uint64_t mipLevelOffset(const TextureView& t, uint32_t level) {
  uint64_t offset = 0;
  for (uint32_t l = 0; l < level; ++l)
    offset += uint64_t(mipLevelSize(t.width, l)) * mipLevelSize(t.height, l) * t.channels;
  return offset;
}

// One level of a texture, as the bilinear lookup reads it.
struct TextureLevel {
  uint64_t offset = 0;  // first element in the texel array
  uint32_t width = 0;
  uint32_t height = 0;
};

CANDELA_FN TextureLevel textureLevel(const TextureView& t, uint32_t level) {
  return {t.offset + mipLevelOffset(t, level), mipLevelSize(t.width, level), mipLevelSize(t.height, level)};
}

struct TexelArrays {
  const TextureView* textures = nullptr;
  uint32_t textureCount = 0;
  const uint8_t* texelBytes = nullptr;
  const float* texelFloats = nullptr;
};

CANDELA_FN float srgbToLinear(float c) {
  return c <= 0.04045f ? c * (1.0f / 12.92f) : powf((c + 0.055f) * (1.0f / 1.055f), 2.4f);
}

// Maps an integer texel coordinate into [0, size).
CANDELA_FN int wrapTexel(int i, int size, TextureWrap wrap) {
  switch (wrap) {
    case TextureWrap::Clamp: return i < 0 ? 0 : (i >= size ? size - 1 : i);
    case TextureWrap::Mirror: {
      int period = 2 * size;
      int m = i % period;
      if (m < 0) m += period;
      return m < size ? m : period - 1 - m;
    }
    case TextureWrap::Repeat: break;
  }
  int m = i % size;
  return m < 0 ? m + size : m;
}

// One texel of a level as linear RGBA: grey images repeat their channel, two-channel images are grey + alpha.
CANDELA_FN Vec4 fetchTexel(const TexelArrays& arrays, const TextureView& t, const TextureLevel& level, int x, int y) {
  uint64_t index = level.offset + (uint64_t(y) * level.width + uint64_t(x)) * t.channels;
  float c[4] = {0, 0, 0, 1};
  for (uint32_t k = 0; k < t.channels && k < 4; ++k) {
    if (t.format == TexelFormat::Float32) {
      c[k] = arrays.texelFloats[index + k];
    } else {
      float v = float(arrays.texelBytes[index + k]) * (1.0f / 255.0f);
      bool isAlpha = (t.channels == 4 && k == 3) || (t.channels == 2 && k == 1);
      c[k] = t.srgb && !isAlpha ? srgbToLinear(v) : v;
    }
  }
  switch (t.channels) {
    case 1: return {c[0], c[0], c[0], 1.0f};
    case 2: return {c[0], c[0], c[0], c[1]};
    case 3: return {c[0], c[1], c[2], 1.0f};
    default: return {c[0], c[1], c[2], c[3]};
  }
}

// Bilinear lookup in one level at texture coordinates uv: u to the right, v down the rows (glTF's convention),
// texel centres at half-integers as in OpenGL and CUDA.
CANDELA_FN Vec4 bilinearLookup(const TexelArrays& arrays, const TextureView& t, const TextureLevel& level, Vec2 uv) {
  float x = uv.x * float(level.width) - 0.5f, y = uv.y * float(level.height) - 0.5f;
  if (!isFinite(x) || !isFinite(y)) return fetchTexel(arrays, t, level, 0, 0);
  float fx0 = floorf(x), fy0 = floorf(y);
  float fx = x - fx0, fy = y - fy0;
  // Far-away coordinates would overflow int; a few periods in, every mode has repeated itself.
  constexpr float kLimit = 1 << 24;
  int x0 = int(clampf(fx0, -kLimit, kLimit)), y0 = int(clampf(fy0, -kLimit, kLimit));
  int w = int(level.width), h = int(level.height);
  int xa = wrapTexel(x0, w, t.wrapU), xb = wrapTexel(x0 + 1, w, t.wrapU);
  int ya = wrapTexel(y0, h, t.wrapV), yb = wrapTexel(y0 + 1, h, t.wrapV);
  Vec4 c00 = fetchTexel(arrays, t, level, xa, ya), c10 = fetchTexel(arrays, t, level, xb, ya);
  Vec4 c01 = fetchTexel(arrays, t, level, xa, yb), c11 = fetchTexel(arrays, t, level, xb, yb);
  auto mix = [&](float a, float b, float c, float d) {
    return (a * (1 - fx) + b * fx) * (1 - fy) + (c * (1 - fx) + d * fx) * fy;
  };
  return {mix(c00.x, c10.x, c01.x, c11.x), mix(c00.y, c10.y, c01.y, c11.y), mix(c00.z, c10.z, c01.z, c11.z),
          mix(c00.w, c10.w, c01.w, c11.w)};
}

// Bilinear lookup in the finest level. On the device, through the texture's texture object: the GPU backend makes
// one for every texture with texels (backends/optix/device_textures.h), so a texture without one has none, and the
// host's lookup stays out of the device programs. Inlined at every lookup of every program, its texel formats and
// wrap modes were the larger part of the path tracer's compiled code, and of the compile that a machine's first
// start waits for (docs/performance.md, 'The first start').
CANDELA_FN Vec4 sampleTexture(const TexelArrays& arrays, int32_t index, Vec2 uv) {
  const TextureView& t = arrays.textures[index];
#if defined(__CUDA_ARCH__)
  if (t.deviceTexture == 0) return {1, 1, 1, 1};
  float4 v = tex2DLod<float4>(cudaTextureObject_t(t.deviceTexture), uv.x, uv.y, 0.0f);
  return {v.x, v.y, v.z, v.w};
#else
  if (t.width == 0 || t.height == 0) return {1, 1, 1, 1};
  return bilinearLookup(arrays, t, textureLevel(t, 0), uv);
#endif
}

}  // namespace candela
