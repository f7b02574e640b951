#pragma once
#include <cstring>

#include "core/math.h"
#include "kernel/curve_attributes.h"
#include "kernel/hit.h"
#include "kernel/scene_view.h"
#include "kernel/texture_filtering.h"
#include "kernel/triangle_attributes.h"

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
  TextureFootprint footprint;  // what the material's lookups average over (none: the finest level)
};

// The surface of a curve at `hit`: its tangent runs along the curve (a hair fibre's axis, hair.h) and its uv are
// u along the curve and v across it (curve_attributes.h).
CANDELA_FN SurfaceInteraction makeCurveInteraction(const SceneView& scene, const Hit& hit, const Ray& ray) {
  const CurveHitGeometry g = curveHitGeometry(scene, hit, ray);
  SurfaceInteraction si;
  si.position = g.position;
  si.geometricNormal = g.normal;
  si.shadingNormal = g.normal;
  si.tangent = g.dpdu;
  si.uv = {clampf(hit.b1, 0.0f, 1.0f), 0.5f * (1.0f - g.h)};
  si.materialId = g.material;
  return si;
}

// The surface that `ray` meets at `hit`.
CANDELA_FN SurfaceInteraction makeInteraction(const SceneView& scene, const Hit& hit, const Ray& ray) {
  if (isCurveHit(scene, hit)) return makeCurveInteraction(scene, hit, ray);
  const HitTriangle tri = hitTriangle(scene, hit);
  const InstanceRecord& inst = *tri.instance;
  const MeshRecord& mesh = *tri.mesh;

  SurfaceInteraction si;
  si.position = inst.objectToWorld.point(interpolate(scene.positions, tri));
  si.geometricNormal = normalize(windingNormal(scene, tri));
  si.shadingNormal = si.geometricNormal;
  if (mesh.hasNormals) {
    Vec3 ns = inst.normalToWorld.vector(interpolate(scene.normals, tri));
    float len = length(ns);
    if (len > 0.0f) si.shadingNormal = faceForward(ns / len, si.geometricNormal);
  }
  if (mesh.hasUvs) si.uv = interpolate(scene.uvs, tri);
  if (mesh.hasTangents) {
    si.tangent = inst.objectToWorld.vector(interpolateDirection(scene.tangents, tri));
    si.bitangentSign = scene.tangents[tri.v0].w < 0.0f ? -1.0f : 1.0f;
  }
  if (mesh.hasColors) si.color = interpolate(scene.colors, tri);
  si.materialId = scene.triangleMaterials[tri.triangle];
  return si;
}

// The material at `hit`, a triangle's or a curve's.
CANDELA_FN uint32_t hitMaterial(const SceneView& scene, const Hit& hit) {
  return isCurveHit(scene, hit) ? hitCurveSegment(scene, hit).material
                                : scene.triangleMaterials[hitTriangle(scene, hit).triangle];
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
