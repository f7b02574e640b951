#include "scene/loaders/normal_generation.h"

#include <tbb/parallel_for.h>

#include <cmath>

namespace candela {

namespace {

float cornerAngle(Vec3 p, Vec3 a, Vec3 b) {
  Vec3 u = a - p, v = b - p;
  float lu = length(u), lv = length(v);
  if (!(lu > 0.0f) || !(lv > 0.0f)) return 0.0f;
  return std::acos(clampf(dot(u, v) / (lu * lv), -1.0f, 1.0f));
}

}  // namespace

std::vector<Vec3> generateCornerNormals(const NormalGenerationInput& in) {
  const std::vector<Vec3>& p = *in.positions;
  const size_t n = in.triangleCount;
  std::vector<Vec3> faceNormals(n);
  tbb::parallel_for(size_t(0), n, [&](size_t t) {
    if (!in.needsNormals[t]) return;
    const uint32_t* c = in.cornerPositions + 3 * t;
    Vec3 cr = cross(p[c[1]] - p[c[0]], p[c[2]] - p[c[0]]);
    float len = length(cr);
    faceNormals[t] = len > 0.0f ? cr / len : Vec3{};
  });

  // Corners around each position, as a compressed adjacency list.
  std::vector<uint32_t> offsets(p.size() + 1, 0);
  for (size_t t = 0; t < n; ++t)
    if (in.needsNormals[t])
      for (int k = 0; k < 3; ++k) ++offsets[in.cornerPositions[3 * t + k] + 1];
  for (size_t i = 0; i < p.size(); ++i) offsets[i + 1] += offsets[i];
  std::vector<uint32_t> corners(offsets.back());
  {
    std::vector<uint32_t> fill(offsets.begin(), offsets.end() - 1);
    for (size_t t = 0; t < n; ++t)
      if (in.needsNormals[t])
        for (uint32_t k = 0; k < 3; ++k) corners[fill[in.cornerPositions[3 * t + k]]++] = uint32_t(3 * t + k);
  }

  const float cosCrease = std::cos(in.creaseDegrees * kPi / 180.0f);
  std::vector<Vec3> normals(3 * n);
  tbb::parallel_for(size_t(0), n, [&](size_t t) {
    if (!in.needsNormals[t]) return;
    uint32_t group = in.smoothingGroups[t];
    Vec3 own = faceNormals[t];
    for (int k = 0; k < 3; ++k) {
      uint32_t pos = in.cornerPositions[3 * t + k];
      Vec3 sum{};
      for (uint32_t i = offsets[pos]; i < offsets[pos + 1]; ++i) {
        uint32_t corner = corners[i], other = corner / 3;
        bool smoothWith = other == t || (group != 0 ? in.smoothingGroups[other] == group
                                                    : in.smoothingGroups[other] == 0 &&
                                                          dot(own, faceNormals[other]) >= cosCrease);
        if (!smoothWith) continue;
        const uint32_t* c = in.cornerPositions + 3 * other;
        uint32_t j = corner % 3;
        sum += faceNormals[other] * cornerAngle(p[c[j]], p[c[(j + 1) % 3]], p[c[(j + 2) % 3]]);
      }
      float len = length(sum);
      normals[3 * t + k] = len > 0.0f ? sum / len : (length(own) > 0.0f ? own : Vec3{0, 1, 0});
    }
  });
  return normals;
}

}  // namespace candela
