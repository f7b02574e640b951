#pragma once
// The surface at a hit on a curve (kernel/curve.h), from the hit's segment, its parameter u along the curve
// (Hit::b1) and the ray, the same way whichever backend found the hit: Embree's curves and OptiX's report u, and
// everything else is reconstructed here, as triangle_attributes.h does for triangles.
//
// Across the curve this follows pbrt-v4's Curve::RecursiveIntersect: h in [-1, 1] is where the ray meets the curve
// across its width, positive along cross(ray direction, dp/du) (for ribbons, along the ribbon's width, signed so);
// pbrt's v is (1 + h) / 2, and candela's v, which runs the other way (hair.h), (1 - h) / 2. It is measured in the
// curve's object space, where pbrt measures it too.
#include "core/math.h"
#include "kernel/curve.h"
#include "kernel/hit.h"
#include "kernel/kernel_variant.h"
#include "kernel/scene_view.h"

namespace candela {

// Whether `hit` is on a curve: on a mesh of curves, which holds no triangles. Never in the lean kernel
// (kernel/kernel_variant.h), whose scenes have no curves.
CANDELA_FN bool isCurveHit(const SceneView& scene, const Hit& hit) {
  return !kLeanKernel && scene.meshes[scene.instances[hit.instanceId].meshId].curveSegmentCount > 0;
}

CANDELA_FN const CurveSegment& hitCurveSegment(const SceneView& scene, const Hit& hit) {
  const MeshRecord& mesh = scene.meshes[scene.instances[hit.instanceId].meshId];
  return scene.curveSegments[mesh.firstCurveSegment + hit.primitiveId];
}

// The object-space vector that the instance's transform maps to the world-space `w` (normalToWorld is the
// inverse transpose of the transform's linear part).
CANDELA_FN Vec3 worldToObjectVector(const InstanceRecord& instance, Vec3 w) {
  const float* m = instance.normalToWorld.m;
  return {m[0] * w.x + m[4] * w.y + m[8] * w.z, m[1] * w.x + m[5] * w.y + m[9] * w.z,
          m[2] * w.x + m[6] * w.y + m[10] * w.z};
}

struct CurveHitGeometry {
  Vec3 position;  // world space
  Vec3 normal;    // world space, unit: the tube's outward normal, the ribbon's, or facing the ray on a flat curve
  Vec3 dpdu;      // world space, along the curve (not normalised)
  float h = 0.0f;
  uint32_t material = 0;
};

// A segment's four control points and their radii, in object space.
struct CurveControlPoints {
  Vec3 p[kCurveControlPoints];
  float radius[kCurveControlPoints];
};

CANDELA_FN CurveControlPoints curveControlPoints(const SceneView& scene, const MeshRecord& mesh,
                                                 const CurveSegment& segment) {
  CurveControlPoints c;
  for (uint32_t i = 0; i < kCurveControlPoints; ++i) {
    const Vec4 v = scene.curveVertices[mesh.firstCurveVertex + segment.firstVertex + i];
    c.p[i] = {v.x, v.y, v.z};
    c.radius[i] = v.w;
  }
  return c;
}

// The curve's radius at u, in object space.
CANDELA_FN float curveRadiusAt(const SceneView& scene, const MeshRecord& mesh, const CurveSegment& segment, float u) {
  return cubicBezier(curveControlPoints(scene, mesh, segment).radius, clampf(u, 0.0f, 1.0f));
}

// Whether a ray meets a tube's wall from inside at `hit` (its t, segment and u), the ray in the curve's object
// space: the hit's offset from the centre line, across the curve, points along the ray. Only a ray that starts on
// the tube can, and it passes (backends/cpu/embree_curve_hits.h says why); Embree's filter tests its own normal,
// OptiX's any-hit program this one.
CANDELA_FN bool meetsTubeFromInside(const SceneView& scene, const Hit& hit, Vec3 objectOrigin, Vec3 objectDirection) {
  const MeshRecord& mesh = scene.meshes[scene.instances[hit.instanceId].meshId];
  const CurveControlPoints c = curveControlPoints(scene, mesh, hitCurveSegment(scene, hit));
  const float u = clampf(hit.b1, 0.0f, 1.0f);
  const Vec3 offset = objectOrigin + objectDirection * hit.t - cubicBezier(c.p, u);
  const Vec3 dpdu = cubicBezierDerivative(c.p, u);
  const Vec3 across = dot(dpdu, dpdu) > 0.0f ? offset - dpdu * (dot(offset, dpdu) / dot(dpdu, dpdu)) : offset;
  return dot(objectDirection, across) > 0.0f;
}

CANDELA_FN CurveHitGeometry curveHitGeometry(const SceneView& scene, const Hit& hit, const Ray& ray) {
  const InstanceRecord& instance = scene.instances[hit.instanceId];
  const MeshRecord& mesh = scene.meshes[instance.meshId];
  const CurveSegment& segment = scene.curveSegments[mesh.firstCurveSegment + hit.primitiveId];
  const CurveControlPoints c = curveControlPoints(scene, mesh, segment);
  const float u = clampf(hit.b1, 0.0f, 1.0f);

  CurveHitGeometry g;
  g.material = segment.material;
  g.position = ray.origin + ray.direction * hit.t;
  const Affine3x4& toWorld = instance.objectToWorld;
  const Vec3 translation{toWorld.m[3], toWorld.m[7], toWorld.m[11]};
  const Vec3 p = worldToObjectVector(instance, g.position - translation);
  const Vec3 d = worldToObjectVector(instance, ray.direction);
  Vec3 dpdu = cubicBezierDerivative(c.p, u);
  if (!(dot(dpdu, dpdu) > 0.0f)) dpdu = c.p[3] - c.p[0];  // a degenerate end: the chord
  const Vec3 along = dot(dpdu, dpdu) > 0.0f ? normalize(dpdu) : Frame::fromNormal(normalize(d)).s;
  const Vec3 offset = p - cubicBezier(c.p, u);  // from the curve's centre line to the hit
  const float radius = fmaxf(cubicBezier(c.radius, u), 1e-30f);
  // Across the curve as the ray sees it; any direction across where the ray runs along the curve.
  Vec3 across = cross(d, along);
  across = dot(across, across) > 0.0f ? normalize(across) : Frame::fromNormal(along).s;

  Vec3 normal;
  float h = dot(offset, across) / radius;
  switch (segment.type) {
    case CurveType::Cylinder: normal = offset - along * dot(offset, along); break;
    case CurveType::Flat: normal = along * dot(d, along) - d; break;
    case CurveType::Ribbon: {
      // The normals' Bézier, as Embree's normal-oriented curves interpolate them.
      Vec3 n[kCurveControlPoints];
      for (uint32_t i = 0; i < kCurveControlPoints; ++i)
        n[i] = scene.curveNormals[mesh.firstCurveNormal + segment.firstVertex + i];
      normal = cubicBezier(n, u);
      normal = normal - along * dot(normal, along);
      const Vec3 width = cross(normal, along);
      if (dot(width, width) > 0.0f) {
        const Vec3 unitWidth = normalize(width);
        h = dot(offset, unitWidth) / radius * (dot(unitWidth, across) < 0.0f ? -1.0f : 1.0f);
      }
      break;
    }
  }
  if (!(dot(normal, normal) > 0.0f)) normal = cross(along, across);
  g.normal = normalize(instance.normalToWorld.vector(normal));
  g.dpdu = toWorld.vector(dpdu);
  g.h = clampf(h, -1.0f, 1.0f);
  return g;
}

}  // namespace candela
