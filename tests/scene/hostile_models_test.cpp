// Models built to make a loader step take quadratic or exponential time, generated here rather than stored: each
// must load (or be refused) in seconds.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <string>

#include "scene/loaders/obj_loader.h"

namespace candela {
namespace {

constexpr double kSecondsAllowed = 20.0;  // each case takes well under a second in a release build

class Stopwatch {
 public:
  double seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

Scene loadObjTimed(const std::string& text, LoadWarnings& warnings) {
  Stopwatch clock;
  Scene s = loadObjText("hostile.obj", text, warnings);
  EXPECT_LT(clock.seconds(), kSecondsAllowed);
  validateScene(s);
  return s;
}

TEST(HostileObj, ManyIdenticalFacesShareTheirNormalsInLinearTime) {
  std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  for (int i = 0; i < 40000; ++i) text += "f 1 2 3\n";
  LoadWarnings warnings;
  Scene s = loadObjTimed(text, warnings);
  ASSERT_EQ(s.triangleCount(), 40000u);
  EXPECT_EQ(s.meshes[0].positions.size(), 3u);
  EXPECT_NEAR(s.meshes[0].normals[0].z, 1.0f, 1e-6f);
}

TEST(HostileObj, AHubVertexOfManyDifferentlyFacingTrianglesGetsASmoothNormal) {
  // A low cone of 300k slices: every triangle faces another way, all within the crease angle of each other.
  const int slices = 300000;
  std::string text = "v 0 0 0.1\n";
  for (int i = 0; i < slices; ++i) {
    double a = 2.0 * M_PI * i / slices;
    text += "v " + std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " 0\n";
  }
  for (int i = 0; i < slices; ++i)
    text += "f 1 " + std::to_string(i + 2) + " " + std::to_string((i + 1) % slices + 2) + "\n";
  LoadWarnings warnings;
  Scene s = loadObjTimed(text, warnings);
  ASSERT_EQ(s.triangleCount(), size_t(slices));
  const Mesh& m = s.meshes[0];
  EXPECT_NEAR(m.normals[m.indices[0]].z, 1.0f, 1e-3f) << "the tip's normal is the cone's axis";
}

TEST(HostileObj, AFaceOfAMillionCornersIsCutIntoAFanWithAWarning) {
  const int corners = 1000000;
  std::string text, face = "f";
  for (int i = 0; i < corners; ++i) {
    double a = 2.0 * M_PI * i / corners;
    text += "v " + std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " 0\n";
    face += ' ';
    face += std::to_string(i + 1);
  }
  LoadWarnings warnings;
  Scene s = loadObjTimed(text + face + "\n", warnings);
  EXPECT_EQ(s.triangleCount(), size_t(corners - 2));
  ASSERT_FALSE(warnings.messages.empty());
  EXPECT_NE(warnings.messages[0].find("hostile.obj: 1 polygons with more than 256 corners"), std::string::npos)
      << warnings.messages[0];
}

TEST(HostileObj, APositionWithManyTextureCoordinatesSharesVerticesInLinearTime) {
  const int uvs = 200000;
  std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  for (int i = 0; i < uvs; ++i) text += "vt " + std::to_string(i) + " 0\n";
  for (int i = 0; i < uvs; ++i) text += "f 1/" + std::to_string(i + 1) + " 2/1 3/1\n";
  LoadWarnings warnings;
  Scene s = loadObjTimed(text, warnings);
  EXPECT_EQ(s.triangleCount(), size_t(uvs));
  EXPECT_EQ(s.meshes[0].positions.size(), size_t(uvs) + 2) << "one vertex per texture coordinate, shared otherwise";
}

}  // namespace
}  // namespace candela
