#pragma once
#include <cstdint>

#include "core/math.h"
#include "kernel/environment.h"
#include "kernel/material.h"
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
};

struct InstanceRecord {
  uint32_t meshId = 0;
  Affine3x4 objectToWorld;
  Affine3x4 normalToWorld;  // inverse transpose of objectToWorld's linear part
};

// One emissive triangle, in world space, for next-event estimation.
struct LightTriangle {
  Vec3 p0, edge1, edge2;
  Vec3 radiance;
  float area = 0.0f;
  uint32_t instanceId = 0;  // where it came from, for textured emission
  uint32_t primitiveId = 0;
  float frontSign = 1.0f;  // -1 under a mirroring instance: the front is then opposite cross(edge1, edge2)
};

// Everything kernel code reads about a scene: plain pointers into host or device memory.
struct SceneView {
  const Vec3* positions = nullptr;  // object space, all meshes back to back
  const Vec3* normals = nullptr;
  const Vec2* uvs = nullptr;       // per vertex, alongside positions (zeros where a mesh has none)
  const Vec4* tangents = nullptr;  // per vertex: unit tangent and bitangent sign (MikkTSpace convention)
  const Vec3* colors = nullptr;    // per vertex, linear RGB; null when no mesh has colours
  const uint32_t* indices = nullptr;  // mesh-local vertex indices, 3 per triangle
  const uint32_t* triangleMaterials = nullptr;
  const MeshRecord* meshes = nullptr;
  const InstanceRecord* instances = nullptr;
  const Material* materials = nullptr;
  TexelArrays texels;
  uint32_t hasCutouts = 0;  // some material is alpha-tested, alpha-blended or back-face culled

  const LightTriangle* lights = nullptr;
  const float* lightCdf = nullptr;  // lightCount + 1 entries, by emitted power
  uint32_t lightCount = 0;
  float lightAreaPdfScale = 0.0f;  // pi / total emitted power: triangle area pdf = scale * luminance(Le)
  float environmentSelectProbability = 0.0f;
  EnvironmentView environment;
};

}  // namespace candela
