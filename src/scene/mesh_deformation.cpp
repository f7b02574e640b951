#include "scene/mesh_deformation.h"

#include <cmath>

#include "scene/scene.h"
#include "scene/transform.h"

namespace candela {

namespace {

Affine3x4 weighted(const Affine3x4& a, float w) {
  Affine3x4 out;
  for (int i = 0; i < 12; ++i) out.m[i] = a.m[i] * w;
  return out;
}

void add(Affine3x4& into, const Affine3x4& a) {
  for (int i = 0; i < 12; ++i) into.m[i] += a.m[i];
}

Affine3x4 multiply(const Affine3x4& a, const Affine3x4& b) { return toAffine(toMat4(a) * toMat4(b)); }

// v normalised, or zero where it has no usable length (the renderer then takes the geometric normal).
Vec3 unitOrZero(Vec3 v) {
  const float l = length(v);
  // Component by component: the reciprocal of a subnormal length overflows to infinity.
  return l > 0.0f && std::isfinite(l) ? Vec3{v.x / l, v.y / l, v.z / l} : Vec3{0, 0, 0};
}

bool usable(Vec3 p, float limit) {
  return std::fabs(p.x) <= limit && std::fabs(p.y) <= limit && std::fabs(p.z) <= limit;  // false for NaN
}

}  // namespace

bool deformMesh(const MeshDeformation& d, const std::vector<float>& weights,
                const std::vector<Affine3x4>& jointMatrices, const Affine3x4& worldToNode, float maxCoordinate,
                Mesh& mesh) {
  const size_t n = d.vertexCount();
  std::vector<Vec3> positions = d.positions, normals = d.normals;
  std::vector<Vec4> tangents = d.tangents;
  for (uint32_t t = 0; t < d.targetCount && t < weights.size(); ++t) {
    const float w = weights[t];
    if (w == 0.0f) continue;
    for (size_t v = 0; v < n; ++v) positions[v] = positions[v] + d.positionDeltas[t * n + v] * w;
    if (!d.normalDeltas.empty() && !normals.empty())
      for (size_t v = 0; v < n; ++v) normals[v] = normals[v] + d.normalDeltas[t * n + v] * w;
    if (!d.tangentDeltas.empty() && !tangents.empty())
      for (size_t v = 0; v < n; ++v) {
        const Vec3 delta = d.tangentDeltas[t * n + v] * w;
        tangents[v] = {tangents[v].x + delta.x, tangents[v].y + delta.y, tangents[v].z + delta.z, tangents[v].w};
      }
  }
  if (d.skin >= 0) {
    for (size_t v = 0; v < n; ++v) {
      // glTF's linear blend skinning: the weighted sum of the joint matrices, applied to the morphed vertex.
      Affine3x4 blend = weighted(Affine3x4{}, 0.0f);
      for (size_t k = d.influences * v; k < d.influences * (v + 1); ++k)
        if (d.jointWeights[k] != 0.0f) add(blend, weighted(jointMatrices[d.joints[k]], d.jointWeights[k]));
      const Affine3x4 toNode = multiply(worldToNode, blend);
      positions[v] = toNode.point(positions[v]);
      if (!normals.empty()) normals[v] = normalTransform(toNode).vector(normals[v]);
      if (!tangents.empty()) {
        const Vec3 t = toNode.vector({tangents[v].x, tangents[v].y, tangents[v].z});
        tangents[v] = {t.x, t.y, t.z, tangents[v].w};
      }
    }
  }
  for (const Vec3& p : positions)
    if (!usable(p, maxCoordinate)) return false;
  for (Vec3& normal : normals) normal = unitOrZero(normal);
  for (Vec4& t : tangents) {
    const Vec3 unit = unitOrZero({t.x, t.y, t.z});
    t = {unit.x, unit.y, unit.z, t.w};
  }
  mesh.positions = std::move(positions);
  if (!mesh.normals.empty()) mesh.normals = std::move(normals);
  if (!mesh.tangents.empty()) mesh.tangents = std::move(tangents);
  return true;
}

}  // namespace candela
