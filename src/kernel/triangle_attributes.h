#pragma once
// Per-vertex attributes at a hit: the hit triangle's three vertices and the barycentric weights of the hit point,
// and their interpolation. Shading (interaction.h) and the cut-out test during traversal (pass_through.h) read
// positions, normals, texture coordinates and tangents through this one lookup, so they agree on every hit.
#include "core/math.h"
#include "kernel/hit.h"
#include "kernel/scene_view.h"

namespace candela {

struct HitTriangle {
  const InstanceRecord* instance = nullptr;
  const MeshRecord* mesh = nullptr;
  uint32_t triangle = 0;            // the scene's triangle: indices[3 * triangle ...], triangleMaterials[triangle]
  uint32_t v0 = 0, v1 = 0, v2 = 0;  // its vertices, as indices into the scene's vertex arrays
  float b0 = 1.0f, b1 = 0.0f, b2 = 0.0f;  // the hit point's barycentric weights
};

CANDELA_FN HitTriangle hitTriangle(const SceneView& scene, const Hit& hit) {
  HitTriangle t;
  t.instance = &scene.instances[hit.instanceId];
  t.mesh = &scene.meshes[t.instance->meshId];
  t.triangle = t.mesh->firstTriangle + hit.primitiveId;
  t.v0 = t.mesh->firstVertex + scene.indices[3 * t.triangle + 0];
  t.v1 = t.mesh->firstVertex + scene.indices[3 * t.triangle + 1];
  t.v2 = t.mesh->firstVertex + scene.indices[3 * t.triangle + 2];
  t.b0 = 1.0f - hit.b1 - hit.b2;
  t.b1 = hit.b1;
  t.b2 = hit.b2;
  return t;
}

// An attribute of the scene's vertex arrays (positions, normals, uvs) at the hit point, in object space.
CANDELA_FN Vec3 interpolate(const Vec3* values, const HitTriangle& t) {
  return values[t.v0] * t.b0 + values[t.v1] * t.b1 + values[t.v2] * t.b2;
}
CANDELA_FN Vec2 interpolate(const Vec2* values, const HitTriangle& t) {
  const Vec2 a = values[t.v0], b = values[t.v1], c = values[t.v2];
  return {a.x * t.b0 + b.x * t.b1 + c.x * t.b2, a.y * t.b0 + b.y * t.b1 + c.y * t.b2};
}
// The direction part (xyz) of tangents stored with their bitangent sign in w.
CANDELA_FN Vec3 interpolateDirection(const Vec4* values, const HitTriangle& t) {
  const Vec4 a = values[t.v0], b = values[t.v1], c = values[t.v2];
  return Vec3{a.x, a.y, a.z} * t.b0 + Vec3{b.x, b.y, b.z} * t.b1 + Vec3{c.x, c.y, c.z} * t.b2;
}

// The triangle's normal as wound by the mesh, in world space, not normalised.
CANDELA_FN Vec3 windingNormal(const SceneView& scene, const HitTriangle& t) {
  const Vec3 p0 = scene.positions[t.v0], p1 = scene.positions[t.v1], p2 = scene.positions[t.v2];
  return t.instance->normalToWorld.vector(cross(p1 - p0, p2 - p0));
}

}  // namespace candela
