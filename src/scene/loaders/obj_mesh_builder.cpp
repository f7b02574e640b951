#include "scene/loaders/obj_mesh_builder.h"

#include <tbb/parallel_for.h>

#include <algorithm>

#include "scene/loaders/normal_generation.h"

namespace candela {

namespace {

template <class T>
void release(std::vector<T>& v) {
  std::vector<T>().swap(v);
}

// A vertex made so far: its attributes, and the next vertex made for the same position.
struct Vertex {
  uint32_t position;
  int32_t uv;      // -1: none
  int32_t normal;  // a normal of the file, or -1 - c for the normal generated at corner c
  uint32_t next;
};
constexpr uint32_t kEnd = ~0u;

// Generated corner normals for the triangles that lack file normals on some corner (whose file normals are
// then dropped); empty when every triangle has them.
std::vector<Vec3> generateMissingNormals(ObjGeometry& g) {
  const size_t triangles = g.triangleCount();
  std::vector<uint8_t> needsNormals(triangles);
  bool any = false;
  for (size_t t = 0; t < triangles; ++t) {
    int32_t* n = &g.cornerNormals[3 * t];
    if (n[0] >= 0 && n[1] >= 0 && n[2] >= 0) continue;
    n[0] = n[1] = n[2] = -1;
    needsNormals[t] = 1;
    any = true;
  }
  if (!any) return {};
  NormalGenerationInput in;
  in.positions = &g.positions;
  in.cornerPositions = g.cornerPositions.data();
  in.triangleCount = triangles;
  in.smoothingGroups = g.smoothingGroups.data();
  in.needsNormals = needsNormals.data();
  return generateCornerNormals(in);
}

bool sameGeneratedNormal(Vec3 a, Vec3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

// Gives every corner its vertex, in order of first use, and overwrites cornerPositions with the vertex indices.
std::vector<Vertex> shareVertices(ObjGeometry& g, const std::vector<Vec3>& generated) {
  std::vector<uint32_t> head(g.positions.size(), kEnd);
  std::vector<Vertex> vertices;
  vertices.reserve(g.positions.size());
  for (size_t c = 0; c < g.cornerPositions.size(); ++c) {
    const uint32_t p = g.cornerPositions[c];
    const int32_t uv = g.cornerUvs[c], n = g.cornerNormals[c];
    uint32_t found = kEnd;
    for (uint32_t v = head[p]; v != kEnd; v = vertices[v].next) {
      const Vertex& x = vertices[v];
      if (x.uv == uv && (n >= 0 ? x.normal == n
                                : x.normal < 0 && sameGeneratedNormal(generated[size_t(-1 - x.normal)], generated[c]))) {
        found = v;
        break;
      }
    }
    if (found == kEnd) {
      found = uint32_t(vertices.size());
      vertices.push_back({p, uv, n >= 0 ? n : -1 - int32_t(c), head[p]});
      head[p] = found;
    }
    g.cornerPositions[c] = found;
  }
  return vertices;
}

}  // namespace

Mesh buildObjMesh(std::string name, ObjGeometry&& g, uint32_t defaultMaterial) {
  std::vector<Vec3> generated = generateMissingNormals(g);
  release(g.smoothingGroups);
  std::vector<Vertex> vertices = shareVertices(g, generated);
  const bool anyUv = std::any_of(g.cornerUvs.begin(), g.cornerUvs.end(), [](int32_t uv) { return uv >= 0; });
  release(g.cornerUvs);
  release(g.cornerNormals);

  Mesh mesh;
  mesh.name = std::move(name);
  mesh.positions.resize(vertices.size());
  mesh.normals.resize(vertices.size());
  if (anyUv) mesh.uvs.resize(vertices.size());
  tbb::parallel_for(size_t(0), vertices.size(), [&](size_t v) {
    const Vertex& x = vertices[v];
    mesh.positions[v] = g.positions[x.position];
    Vec3 n = x.normal >= 0 ? g.normals[size_t(x.normal)] : generated[size_t(-1 - x.normal)];
    float len = length(n);
    mesh.normals[v] = len > 0.0f ? n / len : n;
    if (anyUv) mesh.uvs[v] = x.uv >= 0 ? Vec2{g.uvs[size_t(x.uv)].x, 1.0f - g.uvs[size_t(x.uv)].y} : Vec2{};
  });
  mesh.indices = std::move(g.cornerPositions);
  mesh.triangleMaterials = std::move(g.materials);
  for (uint32_t& m : mesh.triangleMaterials)
    if (m == kObjNoMaterial) m = defaultMaterial;
  return mesh;
}

}  // namespace candela
