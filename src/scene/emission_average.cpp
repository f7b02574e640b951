#include "scene/emission_average.h"

#include <cmath>

#include "core/sampling.h"
#include "kernel/texture_filtering.h"

namespace candela {

namespace {

// Points per side of a stratified grid over the unit square, carried onto the triangle by an area-preserving map.
constexpr uint32_t kGridSide = 8;

}  // namespace

Vec3 meanTextureOverTriangle(const TexelArrays& arrays, int32_t index, Vec2 uv0, Vec2 uv1, Vec2 uv2) {
  const TextureView& t = arrays.textures[index];
  if (t.width == 0 || t.height == 0) return {1, 1, 1};
  Vec2 e1{uv1.x - uv0.x, uv1.y - uv0.y}, e2{uv2.x - uv0.x, uv2.y - uv0.y};
  float texels = 0.5f * std::fabs(e1.x * e2.y - e1.y * e2.x) * float(t.width) * float(t.height);
  float pointsPerTriangle = 0.5f * float(kGridSide * kGridSide);
  // The level whose texels are about as large as the spacing between the points: each texel there averages the
  // finer ones under it.
  float lod = texels > pointsPerTriangle && std::isfinite(texels) ? 0.5f * std::log2(texels / pointsPerTriangle) : 0.0f;
  LevelPair levels = levelPair(t, clampf(lod, 0.0f, float(t.levels - 1)));
  Vec3 sum;
  for (uint32_t i = 0; i < kGridSide; ++i) {
    for (uint32_t j = 0; j < kGridSide; ++j) {
      Vec2 b = sampleUniformTriangle({(float(i) + 0.5f) / kGridSide, (float(j) + 0.5f) / kGridSide});
      Vec2 uv{uv0.x + e1.x * b.x + e2.x * b.y, uv0.y + e1.y * b.x + e2.y * b.y};
      Vec4 c = trilinearLookup(arrays, t, uv, levels);
      sum += Vec3{c.x, c.y, c.z};
    }
  }
  return sum / float(kGridSide * kGridSide);
}

}  // namespace candela
