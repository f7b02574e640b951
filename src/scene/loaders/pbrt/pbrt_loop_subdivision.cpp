#include "scene/loaders/pbrt/pbrt_loop_subdivision.h"

#include <unordered_map>

namespace candela {

namespace {

uint64_t edgeKey(uint32_t a, uint32_t b) { return a < b ? (uint64_t(a) << 32) | b : (uint64_t(b) << 32) | a; }

struct Edge {
  uint32_t a, b;
  uint32_t opposite[2];
  int faces = 0;
  uint32_t midpoint = 0;
};

using EdgeMap = std::unordered_map<uint64_t, Edge>;

EdgeMap edgesOf(const Mesh& mesh) {
  EdgeMap edges;
  edges.reserve(mesh.indices.size());
  for (size_t t = 0; t < mesh.indices.size(); t += 3)
    for (int k = 0; k < 3; ++k) {
      uint32_t a = mesh.indices[t + k], b = mesh.indices[t + (k + 1) % 3], c = mesh.indices[t + (k + 2) % 3];
      Edge& e = edges.try_emplace(edgeKey(a, b), Edge{a, b, {c, c}, 0, 0}).first->second;
      if (e.faces < 2) e.opposite[e.faces] = c;
      ++e.faces;
    }
  return edges;
}

// Every vertex moved to a weighted mean of itself and its neighbours, as Loop's rules do: an interior vertex of
// valence k keeps 1 - k w(k) of itself and takes w(k) of each neighbour; a boundary vertex keeps 1 - 2b and takes
// b of each of its two boundary neighbours; corners and non-manifold vertices stay.
std::vector<Vec3> smoothVertices(const Mesh& mesh, const EdgeMap& edges, float (*interiorWeight)(int), float b) {
  size_t n = mesh.positions.size();
  std::vector<Vec3> neighbourSum(n, Vec3{0, 0, 0}), boundarySum(n, Vec3{0, 0, 0});
  std::vector<int> valence(n, 0), boundaryEdges(n, 0);
  for (const auto& [key, e] : edges) {
    neighbourSum[e.a] += mesh.positions[e.b];
    neighbourSum[e.b] += mesh.positions[e.a];
    ++valence[e.a];
    ++valence[e.b];
    if (e.faces != 2) {
      boundarySum[e.a] += mesh.positions[e.b];
      boundarySum[e.b] += mesh.positions[e.a];
      ++boundaryEdges[e.a];
      ++boundaryEdges[e.b];
    }
  }
  std::vector<Vec3> out(n);
  for (size_t v = 0; v < n; ++v) {
    Vec3 p = mesh.positions[v];
    if (boundaryEdges[v] == 2) {
      out[v] = p * (1.0f - 2.0f * b) + boundarySum[v] * b;
    } else if (boundaryEdges[v] == 0 && valence[v] > 0) {
      float w = interiorWeight(valence[v]);
      out[v] = p * (1.0f - float(valence[v]) * w) + neighbourSum[v] * w;
    } else {
      out[v] = p;
    }
  }
  return out;
}

float loopBeta(int valence) { return valence == 3 ? 3.0f / 16.0f : 3.0f / (8.0f * float(valence)); }

// The weight that puts a vertex on the limit surface (pbrt's loopGamma).
float loopGamma(int valence) { return 1.0f / (float(valence) + 3.0f / (8.0f * loopBeta(valence))); }

Mesh subdivideOnce(const Mesh& in) {
  EdgeMap edges = edgesOf(in);
  Mesh out;
  out.positions = smoothVertices(in, edges, loopBeta, 1.0f / 8.0f);
  for (auto& [key, e] : edges) {
    e.midpoint = uint32_t(out.positions.size());
    Vec3 a = in.positions[e.a], b = in.positions[e.b];
    if (e.faces == 2)
      out.positions.push_back((a + b) * 0.375f + (in.positions[e.opposite[0]] + in.positions[e.opposite[1]]) * 0.125f);
    else
      out.positions.push_back((a + b) * 0.5f);
  }
  out.indices.reserve(in.indices.size() * 4);
  for (size_t t = 0; t < in.indices.size(); t += 3) {
    uint32_t a = in.indices[t], b = in.indices[t + 1], c = in.indices[t + 2];
    uint32_t ab = edges[edgeKey(a, b)].midpoint, bc = edges[edgeKey(b, c)].midpoint, ca = edges[edgeKey(c, a)].midpoint;
    out.indices.insert(out.indices.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
  }
  return out;
}

}  // namespace

Mesh loopSubdivide(Mesh mesh, int levels) {
  for (int level = 0; level < levels && mesh.triangleCount() * 4 <= kMaxSubdividedTriangles; ++level)
    mesh = subdivideOnce(mesh);
  mesh.positions = smoothVertices(mesh, edgesOf(mesh), loopGamma, 1.0f / 5.0f);
  mesh.normals.assign(mesh.positions.size(), Vec3{0, 0, 0});
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
    Vec3 areaNormal = cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
    for (uint32_t v : {a, b, c}) mesh.normals[v] += areaNormal;
  }
  for (Vec3& n : mesh.normals) {
    float len = length(n);
    n = len > 0.0f && isFinite(len) ? n / len : Vec3{0, 0, 1};
  }
  return mesh;
}

}  // namespace candela
