// Models built to make a loader step take quadratic or exponential time, generated here rather than stored: each
// must load (or be refused) in seconds.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <string>

#include "app/scene_loading.h"
#include "scene/loaders/gltf/gltf_loader.h"
#include "scene/loaders/normal_generation.h"
#include "scene/loaders/obj/obj_chunk_parser.h"
#include "scene/loaders/obj/obj_loader.h"
#include "scene/scene_repair.h"
#include "scene/scene_test_files.h"

namespace candela {
namespace {

using nlohmann::json;

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

TEST(HostileObj, AHubOfManyDistinctNormalsStillKeepsTheCreaseBetweenTwoFans) {
  // 300 triangles around the origin facing about +z, 300 facing about +y: more distinct normals than are
  // compared exactly, in two groups 90 degrees apart, far beyond the 45-degree crease.
  const int slices = 300;
  std::vector<Vec3> positions = {{0, 0, 0}};
  std::vector<uint32_t> corners;
  for (int fan = 0; fan < 2; ++fan) {
    const uint32_t first = uint32_t(positions.size());
    for (int i = 0; i <= slices; ++i) {
      float a = 0.5f * kPi * float(i) / slices, c = std::cos(a), s = std::sin(a);
      positions.push_back(fan == 0 ? Vec3{c, s, -0.05f} : Vec3{s, -0.05f, c});
    }
    for (uint32_t i = 0; i < uint32_t(slices); ++i) corners.insert(corners.end(), {0, first + i, first + i + 1});
  }
  std::vector<uint32_t> groups(2 * slices, 0);
  std::vector<uint8_t> needs(2 * slices, 1);
  NormalGenerationInput in;
  in.positions = &positions;
  in.cornerPositions = corners.data();
  in.triangleCount = 2 * slices;
  in.smoothingGroups = groups.data();
  in.needsNormals = needs.data();
  std::vector<Vec3> normals = generateCornerNormals(in);
  for (int t = 0; t < 2 * slices; ++t) {
    Vec3 hub = normals[3 * size_t(t)];
    EXPECT_GT(t < slices ? hub.z : hub.y, 0.99f) << "triangle " << t;
  }
}

// A face of up to kMaxObjFaceCorners corners is cut into a fan with a warning; one of a million is refused, naming
// its line, before its corners are gathered.
TEST(HostileObj, AFaceOfManyCornersIsCutIntoAFanAndOneOfAMillionIsRefused) {
  auto polygon = [](int corners) {
    std::string text, face = "f";
    for (int i = 0; i < corners; ++i) {
      double a = 2.0 * M_PI * i / corners;
      text += "v " + std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " 0\n";
      face += ' ';
      face += std::to_string(i + 1);
    }
    return text + face + "\n";
  };
  LoadWarnings warnings;
  const int corners = int(kMaxObjFaceCorners);
  Scene s = loadObjTimed(polygon(corners), warnings);
  EXPECT_EQ(s.triangleCount(), size_t(corners - 2));
  ASSERT_FALSE(warnings.messages.empty());
  EXPECT_NE(warnings.messages[0].find("hostile.obj: 1 polygons with more than 256 corners"), std::string::npos)
      << warnings.messages[0];
  try {
    loadObjTimed(polygon(1000000), warnings);
    ADD_FAILURE() << "a face of a million corners was accepted";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("hostile.obj:1000001: a face of more than"), std::string::npos) << e.what();
  }
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

// One triangle, positions only, and the node graph a test gives.
json triangleGltf(const json& nodes, const json& rootNodes) {
  return {
      {"asset", {{"version", "2.0"}}},
      {"buffers",
       {{{"byteLength", 36},
         {"uri", "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}}}},
      {"bufferViews", {{{"buffer", 0}, {"byteLength", 36}}}},
      {"accessors", {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}}}},
      {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}}}}}}},
      {"nodes", nodes},
      {"scenes", {{{"nodes", rootNodes}}}},
  };
}

std::string gltfError(const json& gltf) {
  const std::string text = gltf.dump();
  LoadWarnings warnings;
  Stopwatch clock;
  try {
    loadGltfBytes("hostile.gltf", reinterpret_cast<const uint8_t*>(text.data()), text.size(), warnings);
  } catch (const LoadError& e) {
    EXPECT_LT(clock.seconds(), kSecondsAllowed);
    return e.what();
  }
  return "";
}

TEST(HostileGltf, RepeatedChildrenAreRefusedInsteadOfVisitedExponentiallyOften) {
  // Node i lists node i + 1 twice: 2^40 paths to the last node.
  json nodes = json::array();
  for (int i = 0; i < 40; ++i) nodes.push_back({{"mesh", 0}, {"children", {i + 1, i + 1}}});
  nodes.push_back({{"mesh", 0}});
  std::string error = gltfError(triangleGltf(nodes, {0}));
  EXPECT_EQ(error,
            "hostile.gltf: nodes[40]: listed again in nodes[39].children; a node may have only one parent and be "
            "listed once");
}

TEST(HostileGltf, NodesWithTwoParentsOrListedTwiceAsRootsAreRefused) {
  json twoParents = {{{"children", {2}}}, {{"children", {2}}}, {{"mesh", 0}}};
  EXPECT_NE(
      gltfError(triangleGltf(twoParents, {0, 1})).find("hostile.gltf: nodes[2]: listed again in nodes[1].children"),
      std::string::npos);
  EXPECT_NE(gltfError(triangleGltf({{{"mesh", 0}}}, {0, 0})).find("nodes[0]: listed again in scenes[0].nodes"),
            std::string::npos);
}

TEST(HostileGltf, CyclesAreRefusedNamingTheNode) {
  json cycle = {{{"children", {1}}}, {{"mesh", 0}, {"children", {0}}}};
  EXPECT_EQ(gltfError(triangleGltf(cycle, {0})),
            "hostile.gltf: nodes[0]: the node is its own ancestor (a cycle through nodes[1].children)");
}

// A chain of nodes as deep as the loader allows is walked without recursion: a recursive walk overflows the stack
// of a sanitizer build long before this depth.
json nodeChain(int depth) {
  json nodes = json::array();
  for (int i = 0; i < depth; ++i) nodes.push_back({{"translation", {0.001, 0, 0}}, {"children", {i + 1}}});
  nodes.push_back({{"mesh", 0}});
  return nodes;
}

TEST(HostileGltf, ANodeChainAsDeepAsAllowedLoads) {
  const std::string text = triangleGltf(nodeChain(1024), {0}).dump();
  LoadWarnings warnings;
  Scene s = loadGltfBytes("deep.gltf", reinterpret_cast<const uint8_t*>(text.data()), text.size(), warnings);
  ASSERT_EQ(s.instances.size(), 1u);
  EXPECT_NEAR(s.instances[0].objectToWorld.m[3], 1.024f, 1e-4f);
  EXPECT_EQ(gltfError(triangleGltf(nodeChain(1025), {0})),
            "hostile.gltf: nodes[1025]: the node hierarchy is deeper than 1024");
}

TEST(HostileGltf, AFlattenedNodeIsDroppedWithAWarningByTheSceneRepair) {
  test::TempFolder dir;
  json nodes = {{{"mesh", 0}}, {{"mesh", 0}, {"scale", {1, 1, 0}}}};
  std::string file = dir.write("flat.gltf", triangleGltf(nodes, {0, 1}).dump());
  LoadWarnings warnings;
  Scene s = loadGltf(file, warnings);
  repairScene(s, file, warnings);
  EXPECT_EQ(s.instances.size(), 1u);
  ASSERT_EQ(warnings.messages.size(), 1u);
  EXPECT_NE(warnings.messages[0].find("flat.gltf: 1 instances dropped: their transform is not finite, is singular"),
            std::string::npos);
  EXPECT_EQ(loadScene(file).instances.size(), 1u) << "loading repairs";
}

}  // namespace
}  // namespace candela
