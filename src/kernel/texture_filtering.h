#pragma once
// Texture lookups that average over a footprint: the texture-space extent of what one pixel sees at a hit
// (kernel/ray_cone.h gives it), read from the mip pyramid (kernel/texture.h) so that a distant surface returns
// the mean of the texels under the pixel instead of one texel that changes from sample to sample.
#include <cstdint>

#include "kernel/texture.h"

namespace candela {

// How lookups with a footprint filter (RenderSettings::textureFilter, --texture-filter):
// - Finest: bilinear in level 0 whatever the footprint, as without a pyramid;
// - Trilinear: two bilinear lookups in the levels about the footprint's longer axis, blended (isotropic);
// - Anisotropic: up to kMaxAnisotropy trilinear probes along the footprint's longer axis, each in the level of
//   the shorter one (or of the longer divided by kMaxAnisotropy); the texture unit does its own version of this
//   on the GPU (tex2DGrad with maxAnisotropy kMaxAnisotropy).
enum class TextureFilter : uint32_t { Finest = 0, Trilinear, Anisotropic };

constexpr uint32_t kMaxAnisotropy = 16;

// The texture coordinates' change across one pixel's footprint at a hit, along its two axes (the ray-traced
// counterpart of a rasteriser's ddx and ddy of uv). Zero: a point, read at the finest level.
struct TextureFootprint {
  Vec2 dUVdx;
  Vec2 dUVdy;
  TextureFilter filter = TextureFilter::Finest;
};

CANDELA_FN float texelLength(Vec2 duv, const TextureView& t) {
  float x = duv.x * float(t.width), y = duv.y * float(t.height);
  return sqrtf(x * x + y * y);
}

// The level of detail (log2 of the footprint in texels) the trilinear filter reads at, clamped to the stored
// levels; below 0 the texture is magnified and level 0 is read.
CANDELA_FN float trilinearLevel(const TextureView& t, float footprintTexels) {
  float lod = footprintTexels > 0.0f ? log2f(footprintTexels) : 0.0f;
  return clampf(lod, 0.0f, float(t.levels - 1));
}

// The two levels a trilinear lookup at `lod` reads, and how much of the coarser one it takes.
struct LevelPair {
  TextureLevel fine, coarse;
  float blend = 0.0f;  // 0: the fine level alone
};

CANDELA_FN LevelPair levelPair(const TextureView& t, float lod) {
  LevelPair pair;
  uint32_t fine = uint32_t(lod);
  pair.fine = textureLevel(t, fine);
  if (fine + 1 < t.levels && lod > float(fine)) {
    // The coarser level starts where the finer one ends.
    pair.coarse = {pair.fine.offset + uint64_t(pair.fine.width) * pair.fine.height * t.channels,
                   mipLevelSize(t.width, fine + 1), mipLevelSize(t.height, fine + 1)};
    pair.blend = lod - float(fine);
  }
  return pair;
}

// Bilinear lookups in the two levels of `pair`, blended linearly.
CANDELA_FN Vec4 trilinearLookup(const TexelArrays& arrays, const TextureView& t, Vec2 uv, const LevelPair& pair) {
  Vec4 a = bilinearLookup(arrays, t, pair.fine, uv);
  if (pair.blend <= 0.0f) return a;
  Vec4 b = bilinearLookup(arrays, t, pair.coarse, uv);
  float w = pair.blend;
  return {a.x + (b.x - a.x) * w, a.y + (b.y - a.y) * w, a.z + (b.z - a.z) * w, a.w + (b.w - a.w) * w};
}

// The host's anisotropic filter (after EXT_texture_filter_anisotropic): probes spaced evenly along the longer
// axis of the footprint, across its full length, each a trilinear lookup at the level of the footprint's length
// divided by the probe count. Probes no closer than a texel: a footprint under a texel long is magnified, one
// bilinear lookup in level 0 as the texture unit does.
CANDELA_FN Vec4 anisotropicLookup(const TexelArrays& arrays, const TextureView& t, Vec2 uv,
                                  const TextureFootprint& footprint) {
  float lx = texelLength(footprint.dUVdx, t), ly = texelLength(footprint.dUVdy, t);
  Vec2 major = lx >= ly ? footprint.dUVdx : footprint.dUVdy;
  float longer = fmaxf(lx, ly), shorter = fminf(lx, ly);
  if (longer <= 1.0f) return bilinearLookup(arrays, t, textureLevel(t, 0), uv);
  float ratio = shorter > 0.0f ? longer / shorter : float(kMaxAnisotropy);
  uint32_t probes = uint32_t(ceilf(clampf(fminf(ratio, longer), 1.0f, float(kMaxAnisotropy))));
  LevelPair pair = levelPair(t, trilinearLevel(t, longer / float(probes)));
  Vec4 sum;
  for (uint32_t i = 0; i < probes; ++i) {
    float s = (float(i) + 0.5f) / float(probes) - 0.5f;
    Vec4 c = trilinearLookup(arrays, t, {uv.x + major.x * s, uv.y + major.y * s}, pair);
    sum = {sum.x + c.x, sum.y + c.y, sum.z + c.z, sum.w + c.w};
  }
  float inv = 1.0f / float(probes);
  return {sum.x * inv, sum.y * inv, sum.z * inv, sum.w * inv};
}

// A lookup averaged over `footprint`, filtered as it says.
CANDELA_FN Vec4 sampleTextureFiltered(const TexelArrays& arrays, int32_t index, Vec2 uv,
                                      const TextureFootprint& footprint) {
  if (footprint.filter == TextureFilter::Finest) return sampleTexture(arrays, index, uv);
  const TextureView& t = arrays.textures[index];
  float longer = fmaxf(texelLength(footprint.dUVdx, t), texelLength(footprint.dUVdy, t));
  if (!(longer > 0.0f) || !isFinite(longer)) return sampleTexture(arrays, index, uv);
#if defined(__CUDA_ARCH__)
  if (t.deviceTexture != 0) {
    cudaTextureObject_t object = cudaTextureObject_t(t.deviceTexture);
    float4 v = footprint.filter == TextureFilter::Anisotropic
                   ? tex2DGrad<float4>(object, uv.x, uv.y, make_float2(footprint.dUVdx.x, footprint.dUVdx.y),
                                       make_float2(footprint.dUVdy.x, footprint.dUVdy.y))
                   : tex2DLod<float4>(object, uv.x, uv.y, trilinearLevel(t, longer));
    return {v.x, v.y, v.z, v.w};
  }
  // Only textures without texels lack a texture object; the host's filters below stay out of the device program,
  // whose registers and code around the trace calls they would otherwise cost every frame, textured or not.
  return sampleTexture(arrays, index, uv);
#else
  if (t.width == 0 || t.height == 0) return {1, 1, 1, 1};
  if (footprint.filter == TextureFilter::Anisotropic) return anisotropicLookup(arrays, t, uv, footprint);
  return trilinearLookup(arrays, t, uv, levelPair(t, trilinearLevel(t, longer)));
#endif
}

}  // namespace candela
