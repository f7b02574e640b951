#pragma once
#include "kernel/interaction.h"
#include "kernel/material.h"
#include "kernel/scene_view.h"
#include "kernel/texture.h"
#include "kernel/texture_filtering.h"

namespace candela {

// A lookup at a point of the finest level: cut-out tests during traversal and sampled light points, which have no
// footprint.
CANDELA_FN Vec4 lookup(const SceneView& scene, int32_t texture, Vec2 uv) {
  return sampleTexture(scene.texels, texture, uv);
}

// A lookup at a surface point, averaged over its footprint.
CANDELA_FN Vec4 lookup(const SceneView& scene, int32_t texture, const SurfaceInteraction& si) {
  return sampleTextureFiltered(scene.texels, texture, si.uv, si.footprint);
}

// Whether evaluateMaterial or applyNormalMap reads a texture of `m`: only then does a hit need its footprint.
// (The opacity texture is read by materialAlpha, at a point.)
CANDELA_FN bool hasTextures(const Material& m) {
  return m.baseColorTexture != kNoTexture || m.metallicRoughnessTexture != kNoTexture ||
         m.roughnessTexture != kNoTexture || m.metallicTexture != kNoTexture || m.emissionTexture != kNoTexture ||
         m.normalTexture != kNoTexture;
}

// Coverage at uv: opacity times the base colour texture's alpha times the opacity texture.
CANDELA_FN float materialAlpha(const SceneView& scene, const Material& m, Vec2 uv) {
  float alpha = m.opacity;
  if (m.baseColorTexture != kNoTexture) alpha *= lookup(scene, m.baseColorTexture, uv).w;
  if (m.opacityTexture != kNoTexture) alpha *= lookup(scene, m.opacityTexture, uv).x;
  return alpha;
}

// The material's parameters at the surface point with its textures applied (averaged over si.footprint); factors
// multiply texels, and the vertex colour multiplies the base colour, as in glTF.
CANDELA_FN Material evaluateMaterial(const SceneView& scene, const Material& stored, const SurfaceInteraction& si) {
  Material m = stored;
  m.baseColor *= si.color;
  if (m.baseColorTexture != kNoTexture) {
    Vec4 c = lookup(scene, m.baseColorTexture, si);
    m.baseColor *= Vec3{c.x, c.y, c.z};
  }
  if (m.metallicRoughnessTexture != kNoTexture) {
    Vec4 c = lookup(scene, m.metallicRoughnessTexture, si);
    m.roughness *= c.y;
    m.metallic *= c.z;
  }
  if (m.roughnessTexture != kNoTexture) m.roughness *= lookup(scene, m.roughnessTexture, si).x;
  if (m.metallicTexture != kNoTexture) m.metallic *= lookup(scene, m.metallicTexture, si).x;
  if (m.emissionTexture != kNoTexture) {
    Vec4 c = lookup(scene, m.emissionTexture, si);
    m.emission *= Vec3{c.x, c.y, c.z};
  }
  return m;
}

// Bends the shading normal by a tangent-space normal map, the way MikkTSpace-baked maps expect: bitangent =
// sign * cross(normal, tangent) from the interpolated vectors, texel (r, g, b) in [0, 1] as (x, y, z) in
// [-1, 1]. The tangent is re-orthogonalised against the new normal so anisotropic lobes follow it. A perturbed
// normal that would face away from the geometric normal is ignored.
CANDELA_FN void applyNormalMap(const SceneView& scene, const Material& m, SurfaceInteraction& si) {
  if (m.normalTexture == kNoTexture || dot(si.tangent, si.tangent) == 0.0f) return;
  Vec4 c = lookup(scene, m.normalTexture, si);
  Vec3 tn{2.0f * c.x - 1.0f, 2.0f * c.y - 1.0f, 2.0f * c.z - 1.0f};
  Vec3 n = si.shadingNormal;
  Vec3 b = cross(n, si.tangent) * si.bitangentSign;
  Vec3 mapped = si.tangent * tn.x + b * tn.y + n * tn.z;
  float len = length(mapped);
  if (!(len > 0.0f)) return;
  mapped = mapped / len;
  if (dot(mapped, si.geometricNormal) <= 0.0f) return;
  si.shadingNormal = mapped;
  si.tangent = si.tangent - mapped * dot(mapped, si.tangent);
}

}  // namespace candela
