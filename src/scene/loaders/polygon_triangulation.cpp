#include "scene/loaders/polygon_triangulation.h"

#include <cmath>
#include <numeric>

namespace candela {

namespace {

struct Point {
  float x, y;
};

// Twice the signed area of (a, b, c): positive when they turn counter-clockwise.
float orientation(Point a, Point b, Point c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); }

bool strictlyInside(Point p, Point a, Point b, Point c) {
  return orientation(a, b, p) > 0.0f && orientation(b, c, p) > 0.0f && orientation(c, a, p) > 0.0f;
}

// The corners projected onto the coordinate plane the polygon faces most, turned so that the polygon runs
// counter-clockwise. False when the polygon has no area to face with.
bool project(std::span<const Vec3> corners, std::vector<Point>& points) {
  Vec3 n{};  // Newell's normal
  for (size_t i = 0; i < corners.size(); ++i) {
    Vec3 a = corners[i], b = corners[(i + 1) % corners.size()];
    n += Vec3{(a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y)};
  }
  float ax = std::fabs(n.x), ay = std::fabs(n.y), az = std::fabs(n.z);
  if (!(ax > 0.0f || ay > 0.0f || az > 0.0f)) return false;
  points.resize(corners.size());
  for (size_t i = 0; i < corners.size(); ++i) {
    Vec3 c = corners[i];
    if (ax >= ay && ax >= az)
      points[i] = {c.y, n.x > 0.0f ? c.z : -c.z};
    else if (ay >= az)
      points[i] = {c.z, n.y > 0.0f ? c.x : -c.x};
    else
      points[i] = {c.x, n.z > 0.0f ? c.y : -c.y};
  }
  return true;
}

void emit(std::vector<uint32_t>& out, size_t a, size_t b, size_t c) {
  out.insert(out.end(), {uint32_t(a), uint32_t(b), uint32_t(c)});
}

void fan(const std::vector<size_t>& corners, std::vector<uint32_t>& out) {
  for (size_t i = 1; i + 1 < corners.size(); ++i) emit(out, corners[0], corners[i], corners[i + 1]);
}

void quad(std::span<const Vec3> c, const std::vector<Point>& p, bool projected, std::vector<uint32_t>& out) {
  // Diagonal 0-2 lies inside when both halves turn the polygon's way; likewise 1-3.
  bool inside02 = !projected || (orientation(p[0], p[1], p[2]) >= 0.0f && orientation(p[0], p[2], p[3]) >= 0.0f);
  bool inside13 = !projected || (orientation(p[0], p[1], p[3]) >= 0.0f && orientation(p[1], p[2], p[3]) >= 0.0f);
  bool shorter02 = dot(c[2] - c[0], c[2] - c[0]) < dot(c[3] - c[1], c[3] - c[1]);
  if (inside02 && (shorter02 || !inside13)) {
    emit(out, 0, 1, 2);
    emit(out, 0, 2, 3);
  } else {
    emit(out, 0, 1, 3);
    emit(out, 1, 2, 3);
  }
}

bool isEar(const std::vector<Point>& p, const std::vector<size_t>& remaining, size_t a, size_t b, size_t c) {
  if (!(orientation(p[a], p[b], p[c]) > 0.0f)) return false;
  for (size_t q : remaining)
    if (q != a && q != b && q != c && strictlyInside(p[q], p[a], p[b], p[c])) return false;
  return true;
}

// False when clipping ran past its budget of kEarTestsPerCorner corner tests per corner (a polygon whose ears are
// hard to find makes ear clipping cubic) and the rest was cut into a fan.
bool clipEars(const std::vector<Point>& p, std::vector<uint32_t>& out) {
  std::vector<size_t> remaining(p.size());
  std::iota(remaining.begin(), remaining.end(), size_t(0));
  size_t at = 0, triedSinceClip = 0, budget = kEarTestsPerCorner * p.size();
  while (remaining.size() > 3 && triedSinceClip < remaining.size()) {
    const size_t n = remaining.size();
    if (budget < n) {
      fan(remaining, out);
      return false;
    }
    budget -= n;
    at %= n;
    size_t a = remaining[(at + n - 1) % n], b = remaining[at], c = remaining[(at + 1) % n];
    if (isEar(p, remaining, a, b, c)) {
      emit(out, a, b, c);
      remaining.erase(remaining.begin() + std::ptrdiff_t(at));
      triedSinceClip = 0;
    } else {
      ++at;
      ++triedSinceClip;
    }
  }
  fan(remaining, out);  // what is left is a triangle, or has no ear with area
  return true;
}

}  // namespace

bool triangulatePolygon(std::span<const Vec3> corners, std::vector<uint32_t>& triangles) {
  const size_t n = corners.size();
  if (n < 3) return true;
  if (n == 3) {
    emit(triangles, 0, 1, 2);
    return true;
  }
  std::vector<Point> points;
  bool projected = project(corners, points);
  if (n == 4) {
    quad(corners, points, projected, triangles);
    return true;
  }
  if (!projected || n > kMaxEarClippedCorners) {
    std::vector<size_t> all(n);
    std::iota(all.begin(), all.end(), size_t(0));
    fan(all, triangles);
    return !projected;
  }
  return clipEars(points, triangles);
}

}  // namespace candela
