#include <gtest/gtest.h>

#include <cmath>

#include "scene/loaders/polygon_triangulation.h"

namespace candela {
namespace {

std::vector<uint32_t> triangulate(const std::vector<Vec3>& polygon) {
  std::vector<uint32_t> triangles;
  triangulatePolygon(polygon, triangles);
  return triangles;
}

// The area of a planar polygon (Newell), and of the triangles along that polygon's normal: equal, with every
// triangle facing the polygon's way, exactly when the triangles tile the polygon without folding over.
Vec3 newellNormal(const std::vector<Vec3>& p) {
  Vec3 n{};
  for (size_t i = 0; i < p.size(); ++i) n += cross(p[i], p[(i + 1) % p.size()]);
  return n * 0.5f;
}

void expectTiles(const std::vector<Vec3>& polygon, const std::vector<uint32_t>& triangles) {
  ASSERT_EQ(triangles.size(), 3 * (polygon.size() - 2));
  Vec3 n = newellNormal(polygon);
  float area = length(n);
  n = n / area;
  float sum = 0.0f;
  for (size_t t = 0; t < triangles.size(); t += 3) {
    Vec3 a = polygon[triangles[t]], b = polygon[triangles[t + 1]], c = polygon[triangles[t + 2]];
    float facing = dot(cross(b - a, c - a), n) * 0.5f;
    EXPECT_GE(facing, -1e-6f) << "triangle " << t / 3 << " folds over";
    sum += facing;
  }
  EXPECT_NEAR(sum, area, 1e-4f * area);
}

// An L seen from +z: a fan from its first corner would cross the notch.
const std::vector<Vec3> kL = {{2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}, {0, 0, 0}, {2, 0, 0}};

TEST(PolygonTriangulation, ConcavePolygonsAreTiled) {
  expectTiles(kL, triangulate(kL));
  // The same L turned to face -x, and wound the other way round.
  std::vector<Vec3> turned;
  for (Vec3 p : kL) turned.push_back({-p.z, p.y, p.x});
  expectTiles(turned, triangulate(turned));
  std::vector<Vec3> reversed(kL.rbegin(), kL.rend());
  expectTiles(reversed, triangulate(reversed));
}

TEST(PolygonTriangulation, QuadsTakeTheShorterDiagonalThatLiesInside) {
  // A rhombus long along x: the short diagonal joins corners 1 and 3.
  std::vector<Vec3> rhombus = {{-2, 0, 0}, {0, -1, 0}, {2, 0, 0}, {0, 1, 0}};
  EXPECT_EQ(triangulate(rhombus), (std::vector<uint32_t>{0, 1, 3, 1, 2, 3}));
  // A dart whose shorter diagonal 1-3 lies outside it (corner 2 is reflex): 0-2 it is.
  std::vector<Vec3> dart = {{0, 0, 0}, {3, 2.5f, 0}, {2.4f, 2.4f, 0}, {2.5f, 3, 0}};
  expectTiles(dart, triangulate(dart));
  EXPECT_EQ(triangulate(dart), (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));
}

TEST(PolygonTriangulation, LargeAndDegeneratePolygonsStillGiveEveryTriangle) {
  std::vector<Vec3> circle;
  for (int i = 0; i < 300; ++i) circle.push_back({std::cos(float(i) * 0.021f), std::sin(float(i) * 0.021f), 0});
  expectTiles(circle, triangulate(circle));
  std::vector<Vec3> line = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}};
  EXPECT_EQ(triangulate(line).size(), 9u);
  std::vector<Vec3> repeated = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 1, 0}};
  expectTiles(repeated, triangulate(repeated));
}

TEST(PolygonTriangulation, ClippingIsBoundedToLinearTimeAndSaysWhenItFellBackToAFan) {
  // A thick spiral: ear clipping along its outline would test about 5000 corners per corner, cubic in the size.
  std::vector<Vec3> spiral;
  for (int i = 0; i < 128; ++i)
    spiral.push_back({(1.5f + 0.3f * float(i)) * std::cos(0.3f * float(i)),
                      (1.5f + 0.3f * float(i)) * std::sin(0.3f * float(i)), 0});
  for (int i = 127; i >= 0; --i)
    spiral.push_back({(1.0f + 0.3f * float(i)) * std::cos(0.3f * float(i)),
                      (1.0f + 0.3f * float(i)) * std::sin(0.3f * float(i)), 0});
  std::vector<uint32_t> triangles;
  EXPECT_FALSE(triangulatePolygon(spiral, triangles));
  EXPECT_EQ(triangles.size(), 3 * (spiral.size() - 2));

  std::vector<Vec3> circle;  // convex: every corner is an ear, well within the budget
  for (size_t i = 0; i < kMaxEarClippedCorners; ++i)
    circle.push_back({std::cos(float(i) * 0.02f), std::sin(float(i) * 0.02f), 0});
  triangles.clear();
  EXPECT_TRUE(triangulatePolygon(circle, triangles));
  expectTiles(circle, triangles);
  circle.push_back({0, -1, 0});
  triangles.clear();
  EXPECT_FALSE(triangulatePolygon(circle, triangles)) << "more corners than kMaxEarClippedCorners";
}

}  // namespace
}  // namespace candela
