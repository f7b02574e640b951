// pbrt-v4's `curve` shape as the pbrt loader reads it: pbrt-v4's conversions to cubic Bézier segments checked
// against the bases they convert, widths, types and normals, runs of curves grouped into one mesh, hostile
// parameters refused in one line, and hair on curves that loads and renders.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <utility>

#include "io/load_diagnostics.h"
#include "scene/loaders/pbrt/pbrt_curves.h"
#include "scene/scene_repair.h"
#include "support/pbrt_text.h"
#include "support/render_statistics.h"

namespace candela::test {
namespace {

using pbrt::loadError;

void expectNear(Vec3 a, Vec3 b, float tolerance, const std::string& what) {
  EXPECT_NEAR(a.x, b.x, tolerance) << what;
  EXPECT_NEAR(a.y, b.y, tolerance) << what;
  EXPECT_NEAR(a.z, b.z, tolerance) << what;
}

Vec3 bezier(const std::array<Vec3, 4>& p, float t) { return cubicBezier(p.data(), t); }

// Uniform b-splines of degree 3 and 2 on their segment, t in [0, 1], from their basis functions.
Vec3 cubicBSpline(const Vec3 p[4], float t) {
  const float s = 1.0f - t;
  return (p[0] * (s * s * s) + p[1] * (3 * t * t * t - 6 * t * t + 4) +
          p[2] * (-3 * t * t * t + 3 * t * t + 3 * t + 1) + p[3] * (t * t * t)) /
         6.0f;
}
Vec3 quadraticBSpline(const Vec3 p[3], float t) {
  return p[0] * (0.5f * (1 - t) * (1 - t)) + p[1] * (-t * t + t + 0.5f) + p[2] * (0.5f * t * t);
}
Vec3 quadraticBezier(const Vec3 p[3], float t) {
  return p[0] * ((1 - t) * (1 - t)) + p[1] * (2 * t * (1 - t)) + p[2] * (t * t);
}

const Vec3 kPoints[] = {{0, 0, 0}, {1, 2, 0}, {3, -1, 1}, {4, 0.5f, -2}, {6, 1, 0}, {7, -2, 3}};

TEST(PbrtCurveConversion, CubicBSplineToBezier) {
  const std::array<Vec3, 4> b = cubicBSplineToBezier(kPoints);
  for (float t : {0.0f, 0.2f, 0.5f, 0.9f, 1.0f})
    expectNear(bezier(b, t), cubicBSpline(kPoints, t), 1e-5f, "t " + std::to_string(t));
}

TEST(PbrtCurveConversion, QuadraticBSplineToCubicBezier) {
  const std::array<Vec3, 3> q = quadraticBSplineToBezier(kPoints);
  const std::array<Vec3, 4> b = elevateQuadraticBezierToCubic(q.data());
  for (float t : {0.0f, 0.3f, 0.5f, 0.7f, 1.0f}) {
    expectNear(quadraticBezier(q.data(), t), quadraticBSpline(kPoints, t), 1e-5f, "quadratic, t " + std::to_string(t));
    expectNear(bezier(b, t), quadraticBSpline(kPoints, t), 1e-5f, "raised, t " + std::to_string(t));
  }
}

std::string sceneWith(const std::string& shapes) {
  return "LookAt 0 0 -5  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 40\n"
         "Film \"rgb\" \"integer xresolution\" 16 \"integer yresolution\" 16\nWorldBegin\n"
         "LightSource \"infinite\" \"rgb L\" [1 1 1]\n" +
         shapes;
}

std::string pointsOf(size_t count) {
  std::string text;
  for (size_t i = 0; i < count; ++i)
    text +=
        std::to_string(kPoints[i].x) + " " + std::to_string(kPoints[i].y) + " " + std::to_string(kPoints[i].z) + " ";
  return "\"point3 P\" [" + text + "]";
}

TEST(PbrtCurve, BezierCurveWithWidths) {
  LoadWarnings warnings;
  const Scene scene = pbrt::loadText(sceneWith("Shape \"curve\" " + pointsOf(4) +
                                               " \"float width0\" 0.2 \"float width1\" 0.1 \"integer "
                                               "splitdepth\" 5\n"),
                                     &warnings);
  EXPECT_TRUE(warnings.messages.empty()) << warnings.messages.front();
  ASSERT_EQ(scene.meshes.size(), 1u);
  ASSERT_EQ(scene.instances.size(), 1u);
  const Mesh& mesh = scene.meshes[0];
  EXPECT_EQ(mesh.triangleCount(), 0u);
  ASSERT_EQ(mesh.curveSegments.size(), 1u);
  EXPECT_EQ(mesh.curveSegments[0].type, CurveType::Flat) << "pbrt-v4's default type";
  ASSERT_EQ(mesh.curveVertices.size(), 4u);
  for (int i = 0; i < 4; ++i) {
    const Vec4 v = mesh.curveVertices[i];
    expectNear({v.x, v.y, v.z}, kPoints[i], 0.0f, "control point");
    EXPECT_NEAR(v.w, 0.5f * (0.2f - 0.1f * float(i) / 3.0f), 1e-6f) << "half the width, linear along the curve";
  }
  EXPECT_TRUE(mesh.curveNormals.empty());
  EXPECT_EQ(scene.materials[mesh.curveSegments[0].material].type, MaterialType::Diffuse);
}

TEST(PbrtCurve, EachBasisAndDegree) {
  struct Case {
    const char* parameters;
    size_t points, segments;
  };
  for (const Case& c : {Case{"\"string basis\" \"bspline\"", 6, 3},
                        Case{"\"string basis\" \"bspline\" \"integer "
                             "degree\" 2",
                             6, 4},
                        Case{"\"integer degree\" 2", 5, 2}, Case{"", 4, 1}}) {
    const Scene scene = pbrt::loadText(sceneWith("Shape \"curve\" \"string type\" \"cylinder\" " + pointsOf(c.points) +
                                                 " \"float width0\" 0.3 \"float width1\" 0.1 " + c.parameters + "\n"));
    ASSERT_EQ(scene.meshes.size(), 1u) << c.parameters;
    const Mesh& mesh = scene.meshes[0];
    ASSERT_EQ(mesh.curveSegments.size(), c.segments) << c.parameters;
    ASSERT_EQ(mesh.curveVertices.size(), 4 * c.segments);
    // Segments join: each ends where the next starts, radius included; the radii fall from 0.15 to 0.05.
    for (size_t s = 0; s + 1 < c.segments; ++s) {
      const Vec4 end = mesh.curveVertices[4 * s + 3], start = mesh.curveVertices[4 * s + 4];
      expectNear({end.x, end.y, end.z}, {start.x, start.y, start.z}, 1e-5f, c.parameters);
      EXPECT_NEAR(end.w, start.w, 1e-6f);
    }
    EXPECT_NEAR(mesh.curveVertices.front().w, 0.15f, 1e-6f);
    EXPECT_NEAR(mesh.curveVertices.back().w, 0.05f, 1e-6f);
    for (const CurveSegment& segment : mesh.curveSegments) EXPECT_EQ(segment.type, CurveType::Cylinder);
  }
}

TEST(PbrtCurve, RibbonNormals) {
  const Scene scene = pbrt::loadText(
      sceneWith("Shape \"curve\" \"string type\" \"ribbon\" " + pointsOf(4) + " \"normal N\" [0 0 -2  0 1 0]\n"));
  ASSERT_EQ(scene.meshes.size(), 1u);
  const Mesh& mesh = scene.meshes[0];
  ASSERT_EQ(mesh.curveNormals.size(), 4u);
  expectNear(mesh.curveNormals[0], {0, 0, -1}, 1e-6f, "normalised, as pbrt-v4 does");
  expectNear(mesh.curveNormals[3], {0, 1, 0}, 1e-6f, "the end's normal");
  expectNear(mesh.curveNormals[1], {0, 1.0f / 3.0f, -2.0f / 3.0f}, 1e-6f, "a third of the way");
}

// A run of curve directives becomes one mesh placed once; anything between them (here an attribute block, a type
// change) starts another.
TEST(PbrtCurve, RunsOfCurvesShareAMesh) {
  const std::string curve = "Shape \"curve\" " + pointsOf(4) + "\n";
  Scene scene = pbrt::loadText(sceneWith(curve + curve + curve));
  EXPECT_EQ(scene.meshes.size(), 1u);
  EXPECT_EQ(scene.instances.size(), 1u);
  ASSERT_EQ(scene.meshes[0].curveSegments.size(), 3u);
  EXPECT_EQ(scene.meshes[0].curveSegments[2].firstVertex, 8u);

  scene = pbrt::loadText(sceneWith(curve + "AttributeBegin\nTranslate 1 0 0\n" + curve + "AttributeEnd\n" + curve +
                                   "Shape \"curve\" \"string type\" \"cylinder\" " + pointsOf(4) + "\n"));
  EXPECT_EQ(scene.meshes.size(), 4u);
  EXPECT_EQ(scene.instances.size(), 4u);
  EXPECT_FLOAT_EQ(scene.instances[1].objectToWorld.m[3], -1.0f) << "in the transform of its own run (x mirrored)";
}

TEST(PbrtCurve, NamedMaterialMadeLater) {
  const Scene scene = pbrt::loadText(sceneWith("NamedMaterial \"later\"\nShape \"curve\" " + pointsOf(4) +
                                               "\nMakeNamedMaterial \"later\" \"string type\" \"hair\"\n"));
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_EQ(scene.materials[scene.meshes[0].curveSegments[0].material].type, MaterialType::Hair);
}

TEST(PbrtCurve, AreaLightIsLeftOutWithAWarning) {
  LoadWarnings warnings;
  const Scene scene =
      pbrt::loadText(sceneWith("AreaLightSource \"diffuse\" \"rgb L\" [1 1 1]\nShape \"curve\" " + pointsOf(4) + "\n"),
                     &warnings);
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_TRUE(isBlack(scene.materials[scene.meshes[0].curveSegments[0].material].emission));
  bool warned = false;
  for (const std::string& m : warnings.messages)
    warned = warned || m.find("curves do not emit light") != std::string::npos;
  EXPECT_TRUE(warned);
}

TEST(PbrtCurve, HostileParametersAreRefusedInOneLine) {
  const std::pair<std::string, std::string> cases[] = {
      {pointsOf(3), "curve: a degree 3 Bezier curve needs 4 + n * 3 control points, not 3"},
      {pointsOf(5), "curve: a degree 3 Bezier curve needs 4 + n * 3 control points, not 5"},
      {pointsOf(2) + " \"integer degree\" 2", "curve: a degree 2 Bezier curve needs 3 + n * 2 control points, not 2"},
      {pointsOf(3) + " \"string basis\" \"bspline\"", "curve: a degree 3 b-spline needs at least 4 control points"},
      {pointsOf(4) + " \"integer degree\" 4", "curve: 'degree' must be 2 or 3, not 4"},
      {pointsOf(4) + " \"string basis\" \"hermite\"", "curve: unknown basis 'hermite'"},
      {pointsOf(4) + " \"string type\" \"tube\"", "curve: unknown type 'tube'"},
      {pointsOf(4) + " \"float width\" 0", "curve: widths must be finite and positive"},
      {pointsOf(4) + " \"float width1\" -0.1", "curve: widths must be finite and positive"},
      {pointsOf(4) + " \"float width0\" 1e39", "'1e39' is beyond the range of a float (value of 'width0')"},
      {pointsOf(4) + " \"string type\" \"ribbon\"", "curve: a ribbon of 1 segments needs 2 normals 'N', not 0"},
      {pointsOf(4) + " \"string type\" \"ribbon\" \"normal N\" [0 0 1 0 0 0]",
       "curve: a ribbon's normal is zero or not finite"},
      {"\"point3 P\" [0 0 0 1 1 1 2 2 2 3 3 nan]", "'nan' is not a number"},
      {"\"float width\" 1", "curve without 'P'"},
  };
  for (const auto& [parameters, message] : cases) {
    const std::string error = loadError(sceneWith("Shape \"curve\" " + parameters + "\n"));
    EXPECT_NE(error.find("test.pbrt:6: " + message), std::string::npos) << parameters << ": " << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
  }
}

// Hair on round curves, as pbrt-v4's hair scenes have it: it loads, survives the repairs every scene goes through,
// and renders neither black nor as bright as the light behind it.
TEST(PbrtCurve, HairOnCurvesRenders) {
  std::string shapes = "Material \"hair\" \"float eumelanin\" 0.3\n";
  for (int i = 0; i < 40; ++i) {
    const float x = -1.0f + 0.05f * float(i);
    shapes += "Shape \"curve\" \"string type\" \"cylinder\" \"point3 P\" [" + std::to_string(x) + " -2 0 " +
              std::to_string(x + 0.1f) + " -0.7 0.2 " + std::to_string(x - 0.1f) + " 0.7 -0.2 " + std::to_string(x) +
              " 2 0] \"float width0\" 0.03 \"float width1\" 0.01\n";
  }
  LoadWarnings warnings;
  Scene scene = pbrt::loadText(sceneWith(shapes), &warnings);
  repairScene(scene, "test.pbrt", warnings);
  EXPECT_TRUE(warnings.messages.empty()) << warnings.messages.front();
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_EQ(scene.meshes[0].curveSegments.size(), 40u);
  EXPECT_EQ(scene.materials[scene.meshes[0].curveSegments[0].material].type, MaterialType::Hair);
  const PixelStatistics stats = renderOnCpu(scene, 16, 4, 8);
  EXPECT_EQ(stats.invalidSamples, 0u);
  const ImageMean mean = imageMean(stats);
  EXPECT_GT(mean.mean, 0.2) << "not black";
  EXPECT_LT(mean.mean, 0.97) << "the hair is seen";
}

}  // namespace
}  // namespace candela::test
