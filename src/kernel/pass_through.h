#pragma once
// Surfaces a ray crosses without scattering: cut-outs. Backends answer ray queries with the closest hit that
// does not pass through (and shadow rays with any such hit) by calling passesThrough for every candidate hit
// on geometry whose material can let rays through: the OptiX backend from an any-hit program (and culls back
// faces in traversal), the CPU backend from Embree's filter functions. Geometry whose materials cannot is built
// with those calls disabled.
#include "core/rng.h"
#include "kernel/hit.h"
#include "kernel/scene_view.h"
#include "kernel/textured_material.h"

namespace candela {

CANDELA_FN bool isTransmissive(const Material& m) {
  return m.type == MaterialType::Glass || (m.type == MaterialType::Disney && m.specTrans > 0.0f);
}

// Back faces of single-sided opaque materials are not there for rays; refracting materials keep both sides.
CANDELA_FN bool cullsBackFaces(const Material& m) { return m.doubleSided == 0 && !isTransmissive(m); }

// Whether a material's coverage comes from alpha (a mask or blending) rather than being solid.
CANDELA_FN bool usesAlpha(const Material& m) { return m.alphaMode != AlphaMode::Opaque; }

// Whether passesThrough can ever be true for a hit on this material.
CANDELA_FN bool canPassThrough(const Material& m) { return usesAlpha(m) || cullsBackFaces(m); }

// Whether a ray travelling along `direction` meets the hit triangle's back: it travels along the geometric
// normal (the triangle's winding, as makeInteraction orients it).
CANDELA_FN bool meetsBackFace(const SceneView& scene, const Hit& hit, Vec3 direction) {
  const InstanceRecord& inst = scene.instances[hit.instanceId];
  const MeshRecord& mesh = scene.meshes[inst.meshId];
  const uint32_t tri = mesh.firstTriangle + hit.primitiveId;
  const Vec3* p = scene.positions + mesh.firstVertex;
  const Vec3 p0 = p[scene.indices[3 * tri]], p1 = p[scene.indices[3 * tri + 1]], p2 = p[scene.indices[3 * tri + 2]];
  return dot(direction, inst.normalToWorld.vector(cross(p1 - p0, p2 - p0))) > 0.0f;
}

// Whether a ray goes through the surface at a candidate hit untouched: a back face of a single-sided opaque
// material (`backFace()` says whether the ray meets one; it is asked only for such materials), a texel under
// the alpha cutoff, or (alpha blending) with probability 1 - alpha, which is stochastic transparency:
// unbiased for the blended result.
// `randomBits` are drawn once per ray query; hashed with the hit's ids they give each surface the ray meets
// its own decision, and the same one however often and in whatever order traversal reports the hit.
template <class BackFace>
CANDELA_FN bool passesThrough(const SceneView& scene, const Hit& hit, BackFace&& backFace, uint32_t randomBits) {
  const InstanceRecord& inst = scene.instances[hit.instanceId];
  const MeshRecord& mesh = scene.meshes[inst.meshId];
  const uint32_t tri = mesh.firstTriangle + hit.primitiveId;
  const Material& m = scene.materials[scene.triangleMaterials[tri]];
  if (cullsBackFaces(m) && backFace()) return true;
  if (!usesAlpha(m)) return false;
  Vec2 uv;
  if (mesh.hasUvs) {
    const uint32_t i0 = scene.indices[3 * tri], i1 = scene.indices[3 * tri + 1], i2 = scene.indices[3 * tri + 2];
    const Vec2* t = scene.uvs + mesh.firstVertex;
    const float b0 = 1.0f - hit.b1 - hit.b2;
    uv = {t[i0].x * b0 + t[i1].x * hit.b1 + t[i2].x * hit.b2, t[i0].y * b0 + t[i1].y * hit.b1 + t[i2].y * hit.b2};
  }
  const float alpha = materialAlpha(scene, m, uv);
  if (m.alphaMode == AlphaMode::Mask) return alpha < m.alphaCutoff;
  return alpha < 1.0f && bitsToUnitFloat(pcg4d({randomBits, hit.instanceId, hit.primitiveId, 0x5bd1e995u}).x) >= alpha;
}

}  // namespace candela
