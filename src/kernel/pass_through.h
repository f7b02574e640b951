#pragma once
// Surfaces a ray crosses without scattering: cut-outs. Backends answer ray queries with the closest hit that
// does not pass through (and shadow rays with any such hit) by calling passesThrough for every candidate hit
// on geometry whose material can let rays through: the OptiX backend from an any-hit program (and culls back
// faces in traversal), the CPU backend from Embree's filter functions. Geometry whose materials cannot is built
// with those calls disabled.
#include "core/rng.h"
#include "kernel/bsdf/material_models.h"
#include "kernel/hit.h"
#include "kernel/scene_view.h"
#include "kernel/textured_material.h"
#include "kernel/triangle_attributes.h"

namespace candela {

// Back faces of single-sided opaque materials are not there for rays; refracting materials keep both sides.
CANDELA_FN bool cullsBackFaces(const Material& m) { return m.doubleSided == 0 && !isTransmissive(m); }

// Whether a material's coverage comes from alpha (a mask or blending) rather than being solid.
CANDELA_FN bool usesAlpha(const Material& m) { return m.alphaMode != AlphaMode::Opaque; }

// Whether passesThrough can ever be true for a hit on this material.
CANDELA_FN bool canPassThrough(const Material& m) { return usesAlpha(m) || cullsBackFaces(m); }

// Whether a ray travelling along `direction` meets the hit triangle's back: it travels along the geometric
// normal (the triangle's winding, as makeInteraction orients it).
CANDELA_FN bool meetsBackFace(const SceneView& scene, const Hit& hit, Vec3 direction) {
  return dot(direction, windingNormal(scene, hitTriangle(scene, hit))) > 0.0f;
}

// Whether a ray goes through the surface at a candidate hit untouched: a back face of a single-sided opaque
// material (`backFace()` says whether the ray meets one; it is asked only for such materials), a texel under
// the alpha cutoff, or (alpha blending) with probability 1 - alpha, which is stochastic transparency:
// unbiased for the blended result.
// A medium's boundary (Material::interfaceOnly, an alpha mask, so that the backends ask here) passes where the
// scene has no media; in a scene with media the integrator needs the hit, to follow the ray into the medium
// beyond (kernel/media/volume_path.h).
// `randomBits` are drawn once per ray query; hashed with the hit's ids they give each surface the ray meets
// its own decision, and the same one however often and in whatever order traversal reports the hit.
template <class BackFace>
CANDELA_FN bool passesThrough(const SceneView& scene, const Hit& hit, BackFace&& backFace, uint32_t randomBits) {
  const HitTriangle tri = hitTriangle(scene, hit);
  const Material& m = scene.materials[scene.triangleMaterials[tri.triangle]];
  if (m.interfaceOnly) return scene.mediumCount == 0;
  if (cullsBackFaces(m) && backFace()) return true;
  if (!usesAlpha(m)) return false;
  const Vec2 uv = tri.mesh->hasUvs ? interpolate(scene.uvs, tri) : Vec2{};
  const float alpha = materialAlpha(scene, m, uv);
  if (m.alphaMode == AlphaMode::Mask) return alpha < m.alphaCutoff;
  return alpha < 1.0f && bitsToUnitFloat(pcg4d({randomBits, hit.instanceId, hit.primitiveId, 0x5bd1e995u}).x) >= alpha;
}

}  // namespace candela
