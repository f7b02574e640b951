#pragma once
// The mip pyramid of a texture, built once when a scene is packed for rendering (flat_scene.cpp): every level
// below the finest, each the area average of the one above in linear values (sRGB colour decoded before
// averaging and encoded after, alpha and linear data as they are), with the level sizes of kernel/texture.h.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace candela {

// How many values levels 1 on of a width x height texture with `channels` values per texel take.
size_t coarserMipLevelsSize(uint32_t width, uint32_t height, uint32_t channels);

// Writes levels 1 on of a width x height texture with `channels` values per texel to `out`, back to back,
// coarsest last (coarserMipLevelsSize values). 8-bit texels round to the nearest step; `srgb` says their colour
// channels (not alpha: the second of two channels, the fourth of four) are sRGB-encoded, as TextureView::srgb
// does. Rows of a level are computed in parallel.
void writeCoarserMipLevels(const uint8_t* level0, uint32_t width, uint32_t height, uint32_t channels, bool srgb,
                           uint8_t* out);
void writeCoarserMipLevels(const float* level0, uint32_t width, uint32_t height, uint32_t channels, float* out);

// One step down the pyramid: a target texel is the area-weighted mean of the source texels under it, the
// source's columns [x * s, (x + 1) * s) with s = sourceWidth / targetWidth, and likewise for rows. With
// non-power-of-two sizes a target texel covers fractions of source texels, so every source texel weighs the
// same in total and the level's mean equals the source's. Linear values, `channels` per texel.
std::vector<float> downsampleLevel(const std::vector<float>& source, uint32_t sourceWidth, uint32_t sourceHeight,
                                   uint32_t targetWidth, uint32_t targetHeight, uint32_t channels);

}  // namespace candela
