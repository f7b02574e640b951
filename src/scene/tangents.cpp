#include "scene/tangents.h"

#include <algorithm>

namespace candela {

namespace {

Vec3 projectToPlane(Vec3 v, Vec3 n) { return v - n * dot(n, v); }

Vec3 normalizedOrZero(Vec3 v) {
  float len = length(v);
  return len > 0.0f ? v / len : Vec3{};
}

float cornerAngle(Vec3 p, Vec3 a, Vec3 b, Vec3 n) {
  Vec3 e1 = normalizedOrZero(projectToPlane(a - p, n)), e2 = normalizedOrZero(projectToPlane(b - p, n));
  return std::acos(std::clamp(dot(e1, e2), -1.0f, 1.0f));
}

std::vector<Vec3> vertexNormals(const Mesh& mesh) {
  if (!mesh.normals.empty()) {
    std::vector<Vec3> normals(mesh.normals.size());
    std::transform(mesh.normals.begin(), mesh.normals.end(), normals.begin(), normalizedOrZero);
    return normals;
  }
  std::vector<Vec3> sum(mesh.positions.size());
  for (size_t t = 0; t < mesh.triangleCount(); ++t) {
    const uint32_t* v = &mesh.indices[3 * t];
    Vec3 p[3] = {mesh.positions[v[0]], mesh.positions[v[1]], mesh.positions[v[2]]};
    Vec3 n = normalizedOrZero(cross(p[1] - p[0], p[2] - p[0]));
    for (int k = 0; k < 3; ++k) {
      Vec3 a = normalizedOrZero(p[(k + 1) % 3] - p[k]), b = normalizedOrZero(p[(k + 2) % 3] - p[k]);
      sum[v[k]] += n * std::acos(std::clamp(dot(a, b), -1.0f, 1.0f));
    }
  }
  std::transform(sum.begin(), sum.end(), sum.begin(), normalizedOrZero);
  return sum;
}

}  // namespace

std::vector<Vec4> generateTangents(const Mesh& mesh) {
  const size_t vertexCount = mesh.positions.size();
  std::vector<Vec4> tangents(vertexCount, Vec4{1, 0, 0, 1});
  if (mesh.uvs.size() != vertexCount) return tangents;
  std::vector<Vec3> normals = vertexNormals(mesh);
  // Sums per vertex and orientation: [0] orientation-preserving triangles, [1] mirrored ones.
  std::vector<Vec3> tangentSum[2] = {std::vector<Vec3>(vertexCount), std::vector<Vec3>(vertexCount)};
  std::vector<float> angleSum[2] = {std::vector<float>(vertexCount, 0.0f), std::vector<float>(vertexCount, 0.0f)};

  for (size_t t = 0; t < mesh.triangleCount(); ++t) {
    const uint32_t* v = &mesh.indices[3 * t];
    Vec3 p[3] = {mesh.positions[v[0]], mesh.positions[v[1]], mesh.positions[v[2]]};
    Vec2 uv[3];
    for (int k = 0; k < 3; ++k) uv[k] = {mesh.uvs[v[k]].x, -mesh.uvs[v[k]].y};
    Vec3 d1 = p[1] - p[0], d2 = p[2] - p[0];
    float t21x = uv[1].x - uv[0].x, t21y = uv[1].y - uv[0].y;
    float t31x = uv[2].x - uv[0].x, t31y = uv[2].y - uv[0].y;
    float signedArea = t21x * t31y - t21y * t31x;
    if (signedArea == 0.0f) continue;
    int orientation = signedArea > 0.0f ? 0 : 1;
    Vec3 uDirection = (d1 * t31y - d2 * t21y) * (signedArea > 0.0f ? 1.0f : -1.0f);
    for (int k = 0; k < 3; ++k) {
      Vec3 n = normals[v[k]];
      Vec3 tangent = normalizedOrZero(projectToPlane(uDirection, n));
      float angle = cornerAngle(p[k], p[(k + 1) % 3], p[(k + 2) % 3], n);
      tangentSum[orientation][v[k]] += tangent * angle;
      angleSum[orientation][v[k]] += angle;
    }
  }

  for (size_t i = 0; i < vertexCount; ++i) {
    int orientation = angleSum[1][i] > angleSum[0][i] ? 1 : 0;
    Vec3 n = normals[i];
    Vec3 tangent = normalizedOrZero(projectToPlane(tangentSum[orientation][i], n));
    if (dot(tangent, tangent) == 0.0f) tangent = dot(n, n) > 0.0f ? Frame::fromNormal(n).s : Vec3{1, 0, 0};
    tangents[i] = {tangent.x, tangent.y, tangent.z, orientation == 0 ? 1.0f : -1.0f};
  }
  return tangents;
}

}  // namespace candela
