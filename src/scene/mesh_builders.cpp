#include "scene/mesh_builders.h"

namespace candela {

Mesh makeUvSphere(float radius, int segments, int rings, uint32_t materialId, bool inward) {
  Mesh mesh;
  mesh.name = "sphere";
  for (int r = 0; r <= rings; ++r) {
    float theta = kPi * float(r) / float(rings);
    for (int s = 0; s <= segments; ++s) {
      float phi = 2.0f * kPi * float(s) / float(segments);
      Vec3 n{sinf(theta) * cosf(phi), cosf(theta), sinf(theta) * sinf(phi)};
      mesh.positions.push_back(n * radius);
      mesh.normals.push_back(inward ? -n : n);
    }
  }
  auto vertex = [&](int r, int s) { return uint32_t(r * (segments + 1) + s); };
  auto triangle = [&](uint32_t a, uint32_t b, uint32_t c) {
    // (a, b, c) as listed below winds outwards.
    if (inward) std::swap(b, c);
    mesh.indices.insert(mesh.indices.end(), {a, b, c});
    mesh.triangleMaterials.push_back(materialId);
  };
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      uint32_t v00 = vertex(r, s), v01 = vertex(r, s + 1), v10 = vertex(r + 1, s), v11 = vertex(r + 1, s + 1);
      if (r != 0) triangle(v00, v01, v10);
      if (r != rings - 1) triangle(v01, v11, v10);
    }
  return mesh;
}

void appendQuad(Mesh& mesh, Vec3 a, Vec3 b, Vec3 c, Vec3 d, Vec3 towards, uint32_t materialId) {
  uint32_t base = uint32_t(mesh.positions.size());
  mesh.positions.insert(mesh.positions.end(), {a, b, c, d});
  Vec3 n = cross(b - a, c - a);
  bool flip = dot(n, towards - a) < 0.0f;
  uint32_t i1 = flip ? 2 : 1, i2 = flip ? 1 : 2;
  uint32_t j1 = flip ? 3 : 2, j2 = flip ? 2 : 3;
  mesh.indices.insert(mesh.indices.end(), {base, base + i1, base + i2, base, base + j1, base + j2});
  mesh.triangleMaterials.insert(mesh.triangleMaterials.end(), {materialId, materialId});
}

void appendBlock(Mesh& mesh, const Vec3 (&floor)[4], float height, uint32_t materialId) {
  Vec3 centre = (floor[0] + floor[1] + floor[2] + floor[3]) * 0.25f + Vec3{0, height * 0.5f, 0};
  auto up = [&](Vec3 p) { return p + Vec3{0, height, 0}; };
  auto away = [&](Vec3 a, Vec3 b, Vec3 c, Vec3 d) { return (a + b + c + d) * 0.5f - centre; };
  Vec3 t0 = up(floor[0]), t1 = up(floor[1]), t2 = up(floor[2]), t3 = up(floor[3]);
  appendQuad(mesh, t0, t1, t2, t3, away(t0, t1, t2, t3), materialId);
  for (int i = 0; i < 4; ++i) {
    Vec3 a = floor[i], b = floor[(i + 1) % 4];
    appendQuad(mesh, a, b, up(b), up(a), away(a, b, up(b), up(a)), materialId);
  }
}

Material diffuseMaterial(Vec3 albedo, Vec3 emission) {
  return {.type = MaterialType::Diffuse, .baseColor = albedo, .emission = emission};
}

}  // namespace candela
