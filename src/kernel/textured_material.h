#pragma once
#include "core/rng.h"
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
// (The opacity texture is read by materialAlpha, at a point.) A mix may read its amount texture and those of the
// material it chooses: it always takes the footprint.
CANDELA_FN bool hasTextures(const Material& m) {
  return m.type == MaterialType::Mix || m.baseColorTexture != kNoTexture || m.metallicRoughnessTexture != kNoTexture ||
         m.roughnessTexture != kNoTexture || m.metallicTexture != kNoTexture || m.emissionTexture != kNoTexture ||
         m.normalTexture != kNoTexture || m.iridescenceTexture != kNoTexture ||
         m.iridescenceThicknessTexture != kNoTexture;
}

// Coverage at uv: opacity times the base colour texture's alpha times the opacity texture.
CANDELA_FN float materialAlpha(const SceneView& scene, const Material& m, Vec2 uv) {
  float alpha = m.opacity;
  if (m.baseColorTexture != kNoTexture) alpha *= lookup(scene, m.baseColorTexture, uv).w;
  if (m.opacityTexture != kNoTexture) alpha *= lookup(scene, m.opacityTexture, uv).x;
  return alpha;
}

// The radiance `m` emits at the surface point: its emission times its emission texture.
CANDELA_FN Vec3 emittedRadiance(const SceneView& scene, const Material& m, const SurfaceInteraction& si) {
  if (m.emissionTexture == kNoTexture) return m.emission;
  Vec4 c = lookup(scene, m.emissionTexture, si);
  return m.emission * Vec3{c.x, c.y, c.z};
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
  // The film's textures are read only where there is a film.
  if (m.iridescence > 0.0f && m.iridescenceTexture != kNoTexture)
    m.iridescence *= lookup(scene, m.iridescenceTexture, si).x;
  if (m.iridescence > 0.0f && m.iridescenceThicknessTexture != kNoTexture)
    m.iridescenceThickness =
        lerp(lookup(scene, m.iridescenceThicknessTexture, si).y, m.iridescenceThicknessMinimum, m.iridescenceThickness);
  m.emission = emittedRadiance(scene, stored, si);
  return m;
}

// A number in [0, 1) hashed from a shading point, the direction towards the viewer and a mix (pbrt-v4's
// HashFloat(p, wo, ...)): the same vertex of a path always gets the same one, so next-event estimation, BSDF
// sampling and their MIS weights all see one material there, while other points and directions get
// independent ones. The mix's id makes nested mixes choose independently.
CANDELA_FN float mixChoiceNumber(Vec3 p, Vec3 wo, uint32_t mixId) {
  auto bits = [](float f) { return uint32_t(floatAsInt(f)); };
  Uint4 h = pcg4d({bits(p.x), bits(p.y), bits(p.z), mixId});
  h = pcg4d({h.x ^ bits(wo.x), h.y ^ bits(wo.y), h.z ^ bits(wo.z), h.w});
  return bitsToUnitFloat(h.x);
}

// The material whose scattering material `id` shows at the surface point seen from `wo`: `id` itself unless it
// is a mix, else (through mixes of mixes) the one its choices lead to, as pbrt-v4's MixMaterial::ChooseMaterial
// picks: the second material where the hashed number is below the amount. Scene validation keeps chains within
// kMaxMixDepth, so the loop always ends on a material of another type.
CANDELA_FN uint32_t chooseMixedMaterial(const SceneView& scene, uint32_t id, const SurfaceInteraction& si, Vec3 wo) {
  for (uint32_t level = 0; level < kMaxMixDepth; ++level) {
    const Material& m = scene.materials[id];
    if (m.type != MaterialType::Mix) break;
    float amount = m.mixAmount;
    if (m.mixAmountTexture != kNoTexture) amount *= lookup(scene, m.mixAmountTexture, si).x;
    id = m.mixedMaterials[mixChoiceNumber(si.position, wo, id) < amount ? 1 : 0];
  }
  return id;
}

// The material at the shading point si seen from `wo`, textures applied: the surface's own, or for a mix the one
// it chooses there, with the mix's emission.
CANDELA_FN Material evaluateSurfaceMaterial(const SceneView& scene, const SurfaceInteraction& si, Vec3 wo) {
  const uint32_t chosen = chooseMixedMaterial(scene, si.materialId, si, wo);
  Material m = evaluateMaterial(scene, scene.materials[chosen], si);
  if (chosen != si.materialId) m.emission = emittedRadiance(scene, scene.materials[si.materialId], si);
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
