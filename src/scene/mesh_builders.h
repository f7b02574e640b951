#pragma once
#include "scene/scene.h"

namespace candela {

// A latitude-longitude sphere; normals point outwards, or inwards (with matching winding) when `inward`.
Mesh makeUvSphere(float radius, int segments, int rings, uint32_t materialId, bool inward);

// Appends the planar quad (a, b, c, d) as two triangles wound so that the geometric normal faces `towards`.
void appendQuad(Mesh& mesh, Vec3 a, Vec3 b, Vec3 c, Vec3 d, Vec3 towards, uint32_t materialId);

// Appends a block standing on its four floor corners (in order around it), `height` tall, its top and sides
// wound outwards; it has no bottom.
void appendBlock(Mesh& mesh, const Vec3 (&floor)[4], float height, uint32_t materialId);

// A diffuse material of `albedo` that emits `emission`, for generated scenes.
Material diffuseMaterial(Vec3 albedo, Vec3 emission = {0, 0, 0});

}  // namespace candela
