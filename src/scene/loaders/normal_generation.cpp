#include "scene/loaders/normal_generation.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace candela {

namespace {

float cornerAngle(Vec3 p, Vec3 a, Vec3 b) {
  Vec3 u = a - p, v = b - p;
  float lu = length(u), lv = length(v);
  if (!(lu > 0.0f) || !(lv > 0.0f)) return 0.0f;
  return std::acos(clampf(dot(u, v) / (lu * lv), -1.0f, 1.0f));
}

bool lexicographicLess(Vec3 a, Vec3 b) {
  if (a.x != b.x) return a.x < b.x;
  if (a.y != b.y) return a.y < b.y;
  return a.z < b.z;
}
bool same(Vec3 a, Vec3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

// Above this many distinct face normals at one position, the crease test compares each normal with the means of
// kDirectionCells cells of directions instead of with every other normal (linear instead of quadratic time).
constexpr size_t kMaxExactlyCreasedNormals = 256;
constexpr int kDirectionCellsPerSide = 16;  // octahedral cells, each about 11 degrees across
constexpr int kDirectionCells = kDirectionCellsPerSide * kDirectionCellsPerSide;

int directionCell(Vec3 n) {
  float l1 = std::fabs(n.x) + std::fabs(n.y) + std::fabs(n.z);
  float u = n.x / l1, v = n.y / l1;
  if (n.z < 0.0f) {
    float fu = (1.0f - std::fabs(v)) * (u >= 0.0f ? 1.0f : -1.0f);
    v = (1.0f - std::fabs(u)) * (v >= 0.0f ? 1.0f : -1.0f);
    u = fu;
  }
  auto cell = [](float x) {
    return std::clamp(int((x * 0.5f + 0.5f) * kDirectionCellsPerSide), 0, kDirectionCellsPerSide - 1);
  };
  return cell(u) * kDirectionCellsPerSide + cell(v);
}

// The corners of one position, by kind: smoothing-group corners sorted by group, group-0 corners by face normal.
struct Corner {
  uint32_t corner;
  uint32_t group;
  Vec3 faceNormal;
  Vec3 weighted;  // face normal times the corner's angle
};

// A run of group-0 corners with one face normal, and the weighted normals it smooths with.
struct NormalRun {
  size_t begin, end;
  Vec3 normal;
  Vec3 weight{};  // sum of its corners' weighted normals
  Vec3 sum{};     // of the runs within the crease angle, itself included
};

class PositionSmoother {
 public:
  PositionSmoother(const NormalGenerationInput& in, const std::vector<Vec3>& faceNormals, std::vector<Vec3>& normals)
      : in_(in), faceNormals_(faceNormals), normals_(normals), cosCrease_(std::cos(in.creaseDegrees * kPi / 180.0f)) {}

  // Writes the normals of the corners listed in corners[begin, end), all at one position.
  void smooth(const uint32_t* corners, size_t count) {
    const std::vector<Vec3>& p = *in_.positions;
    grouped_.clear();
    creased_.clear();
    for (size_t i = 0; i < count; ++i) {
      uint32_t corner = corners[i], t = corner / 3, k = corner % 3;
      const uint32_t* c = in_.cornerPositions + 3 * t;
      Vec3 n = faceNormals_[t];
      Corner entry{corner, in_.smoothingGroups[t], n, n * cornerAngle(p[c[k]], p[c[(k + 1) % 3]], p[c[(k + 2) % 3]])};
      (entry.group != 0 ? grouped_ : creased_).push_back(entry);
    }
    smoothGroups();
    smoothCreased();
  }

 private:
  // Corners of a smoothing group smooth with every corner of that group at the position.
  void smoothGroups() {
    std::sort(grouped_.begin(), grouped_.end(), [](const Corner& a, const Corner& b) { return a.group < b.group; });
    for (size_t begin = 0; begin < grouped_.size();) {
      size_t end = begin;
      Vec3 sum{};
      for (; end < grouped_.size() && grouped_[end].group == grouped_[begin].group; ++end)
        sum += grouped_[end].weighted;
      for (size_t i = begin; i < end; ++i) write(grouped_[i], sum);
      begin = end;
    }
  }

  // Corners of no group smooth with those of no group whose face normal is within the crease angle of their own;
  // corners with the same face normal get the same sum, so the test runs once per distinct normal.
  void smoothCreased() {
    std::sort(creased_.begin(), creased_.end(),
              [](const Corner& a, const Corner& b) { return lexicographicLess(a.faceNormal, b.faceNormal); });
    runs_.clear();
    for (size_t begin = 0; begin < creased_.size();) {
      NormalRun run{begin, begin, creased_[begin].faceNormal};
      for (; run.end < creased_.size() && same(creased_[run.end].faceNormal, run.normal); ++run.end)
        run.weight += creased_[run.end].weighted;
      runs_.push_back(run);
      begin = run.end;
    }
    if (runs_.size() <= kMaxExactlyCreasedNormals) {
      for (NormalRun& a : runs_)
        for (const NormalRun& b : runs_)
          if (&a == &b || dot(a.normal, b.normal) >= cosCrease_) a.sum += b.weight;
    } else {
      // Each cell of directions stands for its runs by their summed weight, facing the way of that sum.
      cells_.assign(kDirectionCells, Vec3{});
      for (const NormalRun& r : runs_)
        if (dot(r.normal, r.normal) > 0.0f) cells_[size_t(directionCell(r.normal))] += r.weight;
      for (NormalRun& a : runs_) {
        a.sum = a.weight;
        const int own = dot(a.normal, a.normal) > 0.0f ? directionCell(a.normal) : -1;
        for (int c = 0; c < kDirectionCells; ++c) {
          const Vec3 w = c == own ? cells_[size_t(c)] - a.weight : cells_[size_t(c)];
          float len = length(w);
          if (len > 0.0f && dot(a.normal, w / len) >= cosCrease_) a.sum += w;
        }
      }
    }
    for (const NormalRun& r : runs_)
      for (size_t i = r.begin; i < r.end; ++i) write(creased_[i], r.sum);
  }

  void write(const Corner& c, Vec3 sum) {
    float len = length(sum);
    normals_[c.corner] = len > 0.0f ? sum / len : (length(c.faceNormal) > 0.0f ? c.faceNormal : Vec3{0, 1, 0});
  }

  const NormalGenerationInput& in_;
  const std::vector<Vec3>& faceNormals_;
  std::vector<Vec3>& normals_;
  const float cosCrease_;
  std::vector<Corner> grouped_, creased_;
  std::vector<NormalRun> runs_;
  std::vector<Vec3> cells_;
};

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
    Vec3 unit = len > 0.0f ? cr / len : Vec3{};
    faceNormals[t] = isFinite(unit) ? unit : Vec3{};  // NaN would break the sorting by normal below
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

  std::vector<Vec3> normals(3 * n);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, p.size()), [&](const tbb::blocked_range<size_t>& range) {
    PositionSmoother smoother(in, faceNormals, normals);
    for (size_t pos = range.begin(); pos < range.end(); ++pos)
      if (offsets[pos + 1] > offsets[pos]) smoother.smooth(&corners[offsets[pos]], offsets[pos + 1] - offsets[pos]);
  });
  return normals;
}

}  // namespace candela
