#pragma once
#include "core/math.h"
#include "kernel/texture.h"

namespace candela {

// The mean of texture `index` over the triangle with texture coordinates uv0, uv1, uv2: stratified points over
// the triangle, each a trilinear lookup in the mip level where the triangle covers about as many texels as there
// are points, so that every texel under it counts. Light sampling weighs emissive triangles by it: a triangle
// whose emission texture is black there gets no shadow rays (its light still arrives by BSDF sampling, which
// MIS then weighs fully), and bright parts of an emission map get the most.
Vec3 meanTextureOverTriangle(const TexelArrays& arrays, int32_t index, Vec2 uv0, Vec2 uv1, Vec2 uv2);

}  // namespace candela
