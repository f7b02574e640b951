#pragma once
#include <cstring>

#include "core/math.h"
#include "kernel/hit.h"
#include "kernel/scene_view.h"

namespace candela {

struct SurfaceInteraction {
  Vec3 position;
  Vec3 geometricNormal;  // unit, as wound by the mesh
  Vec3 shadingNormal;    // unit, on the same side as geometricNormal
  Vec3 tangent;          // world space, not normalised; zero when the mesh has no tangents
  float bitangentSign = 1.0f;
  Vec2 uv;
  Vec3 color{1, 1, 1};  // the vertex colour, white where the mesh has none
  uint32_t materialId = 0;
};

CANDELA_FN SurfaceInteraction makeInteraction(const SceneView& scene, const Hit& hit) {
  const InstanceRecord& inst = scene.instances[hit.instanceId];
  const MeshRecord& mesh = scene.meshes[inst.meshId];
  uint32_t tri = mesh.firstTriangle + hit.primitiveId;
  uint32_t i0 = scene.indices[3 * tri + 0], i1 = scene.indices[3 * tri + 1], i2 = scene.indices[3 * tri + 2];
  const Vec3* p = scene.positions + mesh.firstVertex;
  float b0 = 1.0f - hit.b1 - hit.b2;

  SurfaceInteraction si;
  Vec3 objectPosition = p[i0] * b0 + p[i1] * hit.b1 + p[i2] * hit.b2;
  si.position = inst.objectToWorld.point(objectPosition);
  si.geometricNormal = normalize(inst.normalToWorld.vector(cross(p[i1] - p[i0], p[i2] - p[i0])));
  si.shadingNormal = si.geometricNormal;
  if (mesh.hasNormals) {
    const Vec3* n = scene.normals + mesh.firstVertex;
    Vec3 ns = inst.normalToWorld.vector(n[i0] * b0 + n[i1] * hit.b1 + n[i2] * hit.b2);
    float len = length(ns);
    if (len > 0.0f) si.shadingNormal = faceForward(ns / len, si.geometricNormal);
  }
  if (mesh.hasUvs) {
    const Vec2* uv = scene.uvs + mesh.firstVertex;
    si.uv = {uv[i0].x * b0 + uv[i1].x * hit.b1 + uv[i2].x * hit.b2, uv[i0].y * b0 + uv[i1].y * hit.b1 + uv[i2].y * hit.b2};
  }
  if (mesh.hasTangents) {
    const Vec4* t = scene.tangents + mesh.firstVertex;
    Vec3 objectTangent = Vec3{t[i0].x, t[i0].y, t[i0].z} * b0 + Vec3{t[i1].x, t[i1].y, t[i1].z} * hit.b1 +
                         Vec3{t[i2].x, t[i2].y, t[i2].z} * hit.b2;
    si.tangent = inst.objectToWorld.vector(objectTangent);
    si.bitangentSign = t[i0].w < 0.0f ? -1.0f : 1.0f;
  }
  if (mesh.hasColors) {
    const Vec3* c = scene.colors + mesh.firstVertex;
    si.color = c[i0] * b0 + c[i1] * hit.b1 + c[i2] * hit.b2;
  }
  si.materialId = scene.triangleMaterials[tri];
  return si;
}

CANDELA_FN int32_t floatAsInt(float f) {
#if defined(__CUDA_ARCH__)
  return __float_as_int(f);
#else
  int32_t i;
  memcpy(&i, &f, sizeof i);
  return i;
#endif
}
CANDELA_FN float intAsFloat(int32_t i) {
#if defined(__CUDA_ARCH__)
  return __int_as_float(i);
#else
  float f;
  memcpy(&f, &i, sizeof f);
  return f;
#endif
}

// Moves a ray origin off the surface along the geometric normal, towards `side`, by a few ulps scaled to the
// position's magnitude (Waechter and Binder 2019, Ray Tracing Gems ch. 6). No scene-dependent epsilon.
CANDELA_FN Vec3 offsetRayOrigin(Vec3 p, Vec3 geometricNormal, Vec3 side) {
  constexpr float kOrigin = 1.0f / 32.0f, kFloatScale = 1.0f / 65536.0f, kIntScale = 256.0f;
  Vec3 n = dot(geometricNormal, side) < 0.0f ? -geometricNormal : geometricNormal;
  float pc[3] = {p.x, p.y, p.z}, nc[3] = {n.x, n.y, n.z}, out[3];
  for (int i = 0; i < 3; ++i) {
    int32_t offset = int32_t(kIntScale * nc[i]);
    float pi = intAsFloat(floatAsInt(pc[i]) + (pc[i] < 0.0f ? -offset : offset));
    out[i] = fabsf(pc[i]) < kOrigin ? pc[i] + kFloatScale * nc[i] : pi;
  }
  return {out[0], out[1], out[2]};
}

}  // namespace candela
