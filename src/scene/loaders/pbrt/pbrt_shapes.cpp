#include "scene/loaders/pbrt/pbrt_shapes.h"

#include <algorithm>
#include <cmath>

#include "io/load_diagnostics.h"
#include "scene/loaders/pbrt/pbrt_loop_subdivision.h"
#include "scene/loaders/pbrt/pbrt_ply.h"

namespace candela {

namespace {

constexpr float kDegrees = kPi / 180.0f;
constexpr int kSegmentsPerTurn = 96;  // fine enough that a sphere's outline stays within 0.06% of its radius
constexpr int kRingsPerHalfTurn = 48;
constexpr int kMaxLoopLevels = 6;

// A (columns + 1) x (rows + 1) vertex grid of a parametric surface: `at(u, v)` gives the point and its normal.
Mesh parametricGrid(int columns, int rows, const std::function<std::pair<Vec3, Vec3>(float, float)>& at) {
  Mesh mesh;
  for (int j = 0; j <= rows; ++j)
    for (int i = 0; i <= columns; ++i) {
      float u = float(i) / float(columns), v = float(j) / float(rows);
      auto [p, n] = at(u, v);
      mesh.positions.push_back(p);
      mesh.normals.push_back(n);
      mesh.uvs.push_back({u, v});
    }
  auto index = [&](int i, int j) { return uint32_t(j * (columns + 1) + i); };
  // Triangles that collapse where a row of the grid meets in one point (a sphere's poles, a disk's centre) are
  // left out.
  auto addTriangle = [&](uint32_t a, uint32_t b, uint32_t c) {
    Vec3 pa = mesh.positions[a], pb = mesh.positions[b], pc = mesh.positions[c];
    float scale = dot(pb - pa, pb - pa) + dot(pc - pa, pc - pa);
    if (length(cross(pb - pa, pc - pa)) > 1e-6f * scale) mesh.indices.insert(mesh.indices.end(), {a, b, c});
  };
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i) {
      addTriangle(index(i, j), index(i + 1, j), index(i + 1, j + 1));
      addTriangle(index(i, j), index(i + 1, j + 1), index(i, j + 1));
    }
  windTrianglesAlongNormals(mesh);
  return mesh;
}

int segmentsFor(float phiMaxDegrees) {
  return std::max(3, int(std::ceil(kSegmentsPerTurn * std::clamp(phiMaxDegrees, 0.0f, 360.0f) / 360.0f)));
}

Mesh makeSphere(const PbrtParameters& params) {
  float radius = params.getFloat("radius", 1.0f);
  float zMin = std::clamp(params.getFloat("zmin", -radius), -std::fabs(radius), std::fabs(radius));
  float zMax = std::clamp(params.getFloat("zmax", radius), -std::fabs(radius), std::fabs(radius));
  float phiMax = std::clamp(params.getFloat("phimax", 360.0f), 0.0f, 360.0f) * kDegrees;
  float r = std::fabs(radius) > 0 ? std::fabs(radius) : 1.0f;
  float thetaMin = std::acos(std::clamp(std::min(zMin, zMax) / r, -1.0f, 1.0f));
  float thetaMax = std::acos(std::clamp(std::max(zMin, zMax) / r, -1.0f, 1.0f));
  int rings = std::max(2, int(std::ceil(kRingsPerHalfTurn * (thetaMin - thetaMax) / kPi)));
  return parametricGrid(segmentsFor(phiMax / kDegrees), rings, [&](float u, float v) {
    float phi = u * phiMax, theta = thetaMin + v * (thetaMax - thetaMin);
    Vec3 n{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
    return std::pair{n * radius, n};
  });
}

Mesh makeDisk(const PbrtParameters& params) {
  float height = params.getFloat("height", 0.0f), radius = params.getFloat("radius", 1.0f);
  float inner = params.getFloat("innerradius", 0.0f);
  float phiMax = std::clamp(params.getFloat("phimax", 360.0f), 0.0f, 360.0f) * kDegrees;
  // pbrt's v runs from the rim (0) to the inner radius (1).
  return parametricGrid(segmentsFor(phiMax / kDegrees), 1, [&](float u, float v) {
    float phi = u * phiMax, rho = radius + v * (inner - radius);
    return std::pair{Vec3{rho * std::cos(phi), rho * std::sin(phi), height}, Vec3{0, 0, 1}};
  });
}

Mesh makeCylinder(const PbrtParameters& params) {
  float radius = params.getFloat("radius", 1.0f);
  float zMin = params.getFloat("zmin", -1.0f), zMax = params.getFloat("zmax", 1.0f);
  float phiMax = std::clamp(params.getFloat("phimax", 360.0f), 0.0f, 360.0f) * kDegrees;
  return parametricGrid(segmentsFor(phiMax / kDegrees), 1, [&](float u, float v) {
    float phi = u * phiMax;
    Vec3 n{std::cos(phi), std::sin(phi), 0};
    return std::pair{Vec3{radius * n.x, radius * n.y, zMin + v * (zMax - zMin)}, n};
  });
}

std::vector<uint32_t> checkedIndices(const PbrtParameters& params, const char* name, size_t vertexCount, size_t group) {
  std::vector<int64_t> raw = params.getInts(name);
  if (raw.size() % group != 0)
    params.fail(std::string("'") + name + "' has " + std::to_string(raw.size()) + " entries, not a multiple of " +
                std::to_string(group));
  std::vector<uint32_t> out(raw.size());
  for (size_t i = 0; i < raw.size(); ++i) {
    if (raw[i] < 0 || uint64_t(raw[i]) >= vertexCount)
      params.fail(std::string("'") + name + "' refers to vertex " + std::to_string(raw[i]) + " of " +
                  std::to_string(vertexCount));
    out[i] = uint32_t(raw[i]);
  }
  return out;
}

// Per-vertex normals and texture coordinates of a mesh shape, dropped with a warning when their count is wrong.
void addVertexAttributes(Mesh& mesh, const PbrtParameters& params, const PbrtShapeInputs& inputs,
                         const std::string& shape) {
  std::vector<Vec3> normals = params.getVec3s("N");
  if (!normals.empty() && normals.size() != mesh.positions.size())
    inputs.warn(shape + " normals", "'N' has another count than 'P': normals dropped");
  else
    mesh.normals = std::move(normals);
  std::vector<Vec2> uvs = params.getVec2s("uv");
  if (uvs.empty()) uvs = params.getVec2s("st");  // pbrt-v3
  if (!uvs.empty() && uvs.size() != mesh.positions.size())
    inputs.warn(shape + " uv", "'uv' has another count than 'P': texture coordinates dropped");
  else
    mesh.uvs = std::move(uvs);
}

Mesh makeTriangleMesh(const PbrtParameters& params, const PbrtShapeInputs& inputs) {
  Mesh mesh;
  mesh.positions = params.getVec3s("P");
  if (mesh.positions.empty()) params.fail("trianglemesh without 'P'");
  mesh.indices = checkedIndices(params, "indices", mesh.positions.size(), 3);
  if (mesh.indices.empty()) {
    if (mesh.positions.size() != 3) params.fail("trianglemesh without 'indices' must have exactly 3 points");
    mesh.indices = {0, 1, 2};
  }
  addVertexAttributes(mesh, params, inputs, "trianglemesh");
  return mesh;
}

// Bilinear patches (p00, p10, p01, p11) split into two triangles each along p00-p11.
Mesh makeBilinearMesh(const PbrtParameters& params, const PbrtShapeInputs& inputs) {
  Mesh mesh;
  mesh.positions = params.getVec3s("P");
  if (mesh.positions.empty()) params.fail("bilinearmesh without 'P'");
  std::vector<uint32_t> patches = checkedIndices(params, "indices", mesh.positions.size(), 4);
  if (patches.empty()) {
    if (mesh.positions.size() != 4) params.fail("bilinearmesh without 'indices' must have exactly 4 points");
    patches = {0, 1, 2, 3};
  }
  for (size_t i = 0; i < patches.size(); i += 4) {
    uint32_t p00 = patches[i], p10 = patches[i + 1], p01 = patches[i + 2], p11 = patches[i + 3];
    mesh.indices.insert(mesh.indices.end(), {p00, p10, p11, p00, p11, p01});
  }
  addVertexAttributes(mesh, params, inputs, "bilinearmesh");
  if (mesh.uvs.empty() && mesh.positions.size() == 4) mesh.uvs = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
  return mesh;
}

}  // namespace

void windTrianglesAlongNormals(Mesh& mesh) {
  if (mesh.normals.size() != mesh.positions.size()) return;
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
    Vec3 winding = cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
    Vec3 normal = mesh.normals[a] + mesh.normals[b] + mesh.normals[c];
    if (dot(winding, normal) < 0.0f) std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
  }
}

std::optional<Mesh> makePbrtShape(const std::string& type, const PbrtParameters& params,
                                  const PbrtShapeInputs& inputs) {
  std::optional<Mesh> mesh;
  if (type == "trianglemesh") {
    mesh = makeTriangleMesh(params, inputs);
  } else if (type == "plymesh") {
    std::string file = params.getString("filename", "");
    if (file.empty()) params.fail("plymesh without 'filename'");
    mesh = readPlyMesh(inputs.resolveFile(file));
    if (params.find("displacement")) inputs.warn("plymesh displacement", "displacement is not applied");
  } else if (type == "bilinearmesh") {
    mesh = makeBilinearMesh(params, inputs);
  } else if (type == "loopsubdiv") {
    Mesh control;
    control.positions = params.getVec3s("P");
    if (control.positions.empty()) params.fail("loopsubdiv without 'P'");
    control.indices = checkedIndices(params, "indices", control.positions.size(), 3);
    int levels = std::clamp(params.getInt("levels", 3), 0, kMaxLoopLevels);
    if (params.getInt("levels", 3) > kMaxLoopLevels)
      inputs.warn("loopsubdiv levels", "subdivided " + std::to_string(kMaxLoopLevels) + " levels, not more");
    size_t wanted = control.triangleCount() << (2 * levels);
    mesh = loopSubdivide(std::move(control), levels);
    if (mesh->triangleCount() < wanted)
      inputs.warn("loopsubdiv levels", "subdivision stopped early: the mesh would have grown too large");
  } else if (type == "sphere") {
    mesh = makeSphere(params);
  } else if (type == "disk") {
    mesh = makeDisk(params);
  } else if (type == "cylinder") {
    mesh = makeCylinder(params);
  } else {
    inputs.warn("shape " + type, "candela does not draw '" + type + "' shapes: left out");
    return std::nullopt;
  }
  mesh->triangleMaterials.assign(mesh->triangleCount(), 0);
  return mesh;
}

}  // namespace candela
