#include "scene/loaders/obj/obj_mesh_builder.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <unordered_map>

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

// What makes a corner's vertex: its position, texture coordinate and normal (a generated normal by its value).
struct VertexKey {
  uint32_t position;
  int32_t uv;
  int32_t normal;                     // a normal of the file, or -1 for a generated one
  std::array<uint32_t, 3> generated;  // bits of the generated normal, +0 for -0

  bool operator==(const VertexKey&) const = default;
};

struct VertexKeyHash {
  size_t operator()(const VertexKey& k) const {
    uint64_t h = k.position;
    for (uint32_t x : {uint32_t(k.uv), uint32_t(k.normal), k.generated[0], k.generated[1], k.generated[2]})
      h = (h ^ x) * 0x100000001B3ull;
    return size_t(h ^ (h >> 29));
  }
};

uint32_t bitsOf(float x) {
  uint32_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  return x == 0.0f ? 0u : bits;
}

bool sameGeneratedNormal(Vec3 a, Vec3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

// A position's vertices are found by walking its list; past this many, further ones go into a hash table, so
// that a position with very many distinct attributes costs constant time per corner instead of linear.
constexpr uint32_t kMaxListedVertices = 16;

// Gives every corner its vertex, in order of first use, and overwrites cornerPositions with the vertex indices.
std::vector<Vertex> shareVertices(ObjGeometry& g, const std::vector<Vec3>& generated) {
  std::vector<uint32_t> head(g.positions.size(), kEnd);
  std::vector<uint8_t> listed(g.positions.size(), 0);
  std::unordered_map<VertexKey, uint32_t, VertexKeyHash> crowded;
  std::vector<Vertex> vertices;
  vertices.reserve(g.positions.size());
  for (size_t c = 0; c < g.cornerPositions.size(); ++c) {
    const uint32_t p = g.cornerPositions[c];
    const int32_t uv = g.cornerUvs[c], n = g.cornerNormals[c];
    uint32_t found = kEnd;
    for (uint32_t v = head[p]; v != kEnd; v = vertices[v].next) {
      const Vertex& x = vertices[v];
      if (x.uv == uv &&
          (n >= 0 ? x.normal == n
                  : x.normal < 0 && sameGeneratedNormal(generated[size_t(-1 - x.normal)], generated[c]))) {
        found = v;
        break;
      }
    }
    if (found == kEnd && listed[p] == kMaxListedVertices) {
      VertexKey key{p, uv, n >= 0 ? n : -1, {}};
      if (n < 0) key.generated = {bitsOf(generated[c].x), bitsOf(generated[c].y), bitsOf(generated[c].z)};
      auto [it, added] = crowded.try_emplace(key, uint32_t(vertices.size()));
      if (added) vertices.push_back({p, uv, n >= 0 ? n : -1 - int32_t(c), kEnd});
      found = it->second;
    } else if (found == kEnd) {
      found = uint32_t(vertices.size());
      vertices.push_back({p, uv, n >= 0 ? n : -1 - int32_t(c), head[p]});
      head[p] = found;
      ++listed[p];
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
