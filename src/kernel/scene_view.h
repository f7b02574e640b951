#pragma once
#include <cstddef>
#include <cstdint>

#include "core/math.h"
#include "kernel/curve.h"
#include "kernel/environment.h"
#include "kernel/light_bounds.h"
#include "kernel/material.h"
#include "kernel/media/medium.h"
#include "kernel/media/medium_grid.h"
#include "kernel/scene_arrays.h"
#include "kernel/texture.h"

namespace candela {

// Where one mesh's data starts in the scene's flat arrays.
struct MeshRecord {
  uint32_t firstVertex = 0;
  uint32_t vertexCount = 0;
  uint32_t firstTriangle = 0;  // into `indices` (3 per triangle) and `triangleMaterials`
  uint32_t triangleCount = 0;
  uint32_t hasNormals = 0;
  uint32_t hasUvs = 0;
  uint32_t hasTangents = 0;
  uint32_t hasColors = 0;
  // Curves (kernel/curve.h): a mesh holds these or triangles, never both.
  uint32_t firstCurveVertex = 0;  // into curveVertices
  uint32_t firstCurveNormal = 0;  // into curveNormals, where hasCurveNormals (ribbons)
  uint32_t firstCurveSegment = 0;
  uint32_t curveSegmentCount = 0;
  uint32_t hasCurveNormals = 0;
};

struct InstanceRecord {
  uint32_t meshId = 0;
  Affine3x4 objectToWorld;
  Affine3x4 normalToWorld;     // inverse transpose of objectToWorld's linear part
  MediumInterface media = {};  // indices into SceneView::media
};

// One emissive triangle, in world space, for next-event estimation.
struct LightTriangle {
  Vec3 p0, edge1, edge2;
  Vec3 radiance;
  float area = 0.0f;
  uint32_t instanceId = 0;  // where it came from, for textured emission
  uint32_t primitiveId = 0;
  float frontSign = 1.0f;  // -1 under a mirroring instance: the front is then opposite cross(edge1, edge2)
  // What light sampling weighs it by: pi x area x luminance of the radiance it emits on average, its emission
  // texture's mean over the triangle included. Triangles that emit nothing on average are left out of the table.
  float power = 0.0f;
};

// One node of the light BVH (pbrt-v4's BVHLightSampler), flat in depth-first order: an interior node's first
// child follows it and its second is at childOrLight; a leaf holds the one bounded light at childOrLight (see
// SceneView: a triangle below lightCount, a point or spot light above).
struct LightBvhNode {
  CompactLightBounds bounds;
  uint32_t childOrLight = 0;
  uint32_t isLeaf = 0;
};

// A light at a point or infinitely far away in one direction, sampled by next-event estimation only: no ray
// can hit it, so its samples take no MIS weight. Point and spot lights emit `intensity` (radiant intensity, per
// steradian) from `position`, a spot only within its cone about `direction` with a smooth falloff between cosInner and
// cosOuter; a directional light gives irradiance `intensity` to a surface facing it, arriving along `direction`.
enum class PunctualLightType : uint32_t { Point, Spot, Directional };

struct PunctualLight {
  PunctualLightType type = PunctualLightType::Point;
  Vec3 position;
  Vec3 direction{0, -1, 0};  // unit: where the light goes (spot axis, directional travel)
  Vec3 intensity;
  float cosInner = -1.0f;  // spot only: full intensity within this cone,
  float cosOuter = -1.0f;  // none outside this one
};

// Everything kernel code reads about a scene: plain pointers into host or device memory.
//
// Next-event estimation picks one light among the infinite ones (the environment, each directional light) and the
// bounded ones (emissive triangles, point and spot lights) as pbrt-v4's BVHLightSampler does: each infinite light
// with one fixed probability, the bounded lights together with the rest, and one of them by the light BVH or by
// power. Bounded light i is the triangle lights[i] below lightCount, else punctualLights[i - lightCount]. The point
// and spot lights come first in punctualLights, boundedPunctualLightCount of them, then the directional lights.
struct SceneView {
  // The arrays of kernel/scene_arrays.h, in its order: `const Type* member`, null when the array is empty, and
  // after it its length where the list says counted(name).
#define CANDELA_SCENE_VIEW_ARRAY(Type, member, upload, count, description) \
  const Type* member = nullptr;                                            \
  CANDELA_SCENE_ARRAY_COUNT_MEMBER(count)
  CANDELA_SCENE_ARRAYS(CANDELA_SCENE_VIEW_ARRAY)
#undef CANDELA_SCENE_VIEW_ARRAY
  TexelArrays texels;       // left out of the list, as the environment is (kernel/scene_arrays.h says why)
  uint32_t hasCutouts = 0;  // some material is alpha-tested, alpha-blended or back-face culled
  uint32_t boundedPunctualLightCount = 0;
  float inverseLightPower = 0.0f;  // 1 / the bounded lights' total power (kernel/lights.h)
  float environmentSelectProbability = 0.0f;
  float directionalSelectProbability = 0.0f;  // of each directional light
  float boundedSelectProbability = 0.0f;      // of the bounded lights together
  EnvironmentView environment;
  uint32_t cameraMedium = kNoMedium;  // the medium camera rays start in
};

// Sets the length SceneView holds of a listed array, where it holds one (CANDELA_SCENE_ARRAY_COUNT_FIELD).
inline void setSceneArrayCount(SceneView&, std::nullptr_t, size_t) {}
inline void setSceneArrayCount(SceneView& view, uint32_t SceneView::*count, size_t size) {
  view.*count = uint32_t(size);
}

CANDELA_FN uint32_t boundedLightCount(const SceneView& scene) {
  return scene.lightCount + scene.boundedPunctualLightCount;
}

}  // namespace candela
