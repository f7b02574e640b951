// Skins and morph targets of glTF files: deformed vertices at given times against hand-computed ones, the
// scene cache, hostile skin data, and renders at two times through Backend::setDeformedMeshes.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstring>
#include <limits>

#include "app/scene_loading.h"
#include "backends/cpu/cpu_backend.h"
#include "scene/animation_player.h"
#include "scene/cache/scene_cache.h"
#include "scene/gltf_cache_round_trip.h"
#include "scene/loaders/gltf/gltf_loader.h"
#include "scene/scene_test_files.h"
#include "support/image_expectations.h"
#include "support/vector_expectations.h"

namespace candela {
namespace {

using nlohmann::json;
using test::TempFolder;

constexpr float kSqrtHalf = 0.70710678f;

using test::expectNear;

// A glTF built in memory: accessors of any component type over one buffer.
struct GltfFile {
  json gltf = {{"asset", {{"version", "2.0"}}}, {"bufferViews", json::array()}, {"accessors", json::array()}};
  std::vector<uint8_t> buffer;

  template <class T>
  int add(const std::vector<T>& values, const char* type, int componentType, size_t components) {
    while (buffer.size() % 4 != 0) buffer.push_back(0);
    const size_t offset = buffer.size();
    buffer.resize(offset + values.size() * sizeof(T));
    std::memcpy(buffer.data() + offset, values.data(), values.size() * sizeof(T));
    gltf["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", values.size() * sizeof(T)}});
    gltf["accessors"].push_back({{"bufferView", gltf["bufferViews"].size() - 1},
                                 {"componentType", componentType},
                                 {"count", values.size() / components},
                                 {"type", type}});
    return int(gltf["accessors"].size() - 1);
  }
  int floats(const std::vector<float>& values, const char* type) {
    const size_t components = std::string(type) == "SCALAR" ? 1
                              : std::string(type) == "VEC3" ? 3
                              : std::string(type) == "MAT4" ? 16
                                                            : 4;
    return add(values, type, 5126, components);
  }

  std::string write(const TempFolder& folder) {
    gltf["buffers"] = {{{"byteLength", buffer.size()}, {"uri", "deformed.bin"}}};
    folder.write("deformed.bin", std::string(buffer.begin(), buffer.end()));
    return folder.write("deformed.gltf", gltf.dump());
  }
};

// A quad of height 2 skinned to two joints: node 1 (at the origin) and its child node 2 (at (0, 1, 0)), which
// "Bend" turns from 0 to 90 degrees about z over 1 s. Vertices 0 (0,0,0) and 1 (1,0,0) follow joint 0, vertex 2
// (1,2,0) joint 1, vertex 3 (0,2,0) both by half. The skinned node 0 is moved to (5, 0, 0), which glTF ignores for
// skinned vertices. The quad faces +z, emissive, before a camera at z = 8.
GltfFile skinnedQuad() {
  GltfFile f;
  const int positions = f.floats({0, 0, 0, 1, 0, 0, 1, 2, 0, 0, 2, 0}, "VEC3");
  const int indices = f.add(std::vector<uint16_t>{0, 1, 2, 0, 2, 3}, "SCALAR", 5123, 1);
  const int joints = f.add(std::vector<uint8_t>{0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0}, "VEC4", 5121, 4);
  const int weights = f.floats({1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0.5f, 0.5f, 0, 0}, "VEC4");
  const int inverseBinds =
      f.floats({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -1, 0, 1},
               "MAT4");
  f.gltf["meshes"] = {{{"primitives",
                        {{{"attributes", {{"POSITION", positions}, {"JOINTS_0", joints}, {"WEIGHTS_0", weights}}},
                          {"indices", indices},
                          {"material", 0}}}}}};
  f.gltf["materials"] = {
      {{"emissiveFactor", {1, 1, 1}}, {"pbrMetallicRoughness", {{"baseColorFactor", {0, 0, 0, 1}}}}}};
  f.gltf["skins"] = {{{"joints", {1, 2}}, {"inverseBindMatrices", inverseBinds}}};
  f.gltf["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.1}}}}};
  f.gltf["nodes"] = {{{"mesh", 0}, {"skin", 0}, {"translation", {5, 0, 0}}},
                     {{"children", {2}}},
                     {{"translation", {0, 1, 0}}},
                     {{"camera", 0}, {"translation", {0, 1, 8}}}};
  f.gltf["scenes"] = {{{"nodes", {0, 1, 3}}}};
  const int times = f.floats({0, 1}, "SCALAR");
  const int turns = f.floats({0, 0, 0, 1, 0, 0, kSqrtHalf, kSqrtHalf}, "VEC4");
  f.gltf["animations"] = {{{"name", "Bend"},
                           {"samplers", {{{"input", times}, {"output", turns}}}},
                           {"channels", {{{"sampler", 0}, {"target", {{"node", 2}, {"path", "rotation"}}}}}}}};
  return f;
}

// The world position of vertex `v` of the scene's only instance.
Vec3 worldVertex(const Scene& scene, size_t v) {
  const Instance& instance = scene.instances.at(0);
  return instance.objectToWorld.point(scene.meshes.at(instance.meshId).positions.at(v));
}

TEST(GltfSkins, TwoJointQuadDeformsAsLinearBlendSkinningSays) {
  TempFolder folder;
  Scene scene = loadScene(skinnedQuad().write(folder), SceneLoadOptions{});
  ASSERT_EQ(scene.animation.deformations.size(), 1u);
  ASSERT_EQ(scene.animation.skins.size(), 1u);
  // At rest the joints are where the inverse bind matrices expect them: the bind pose, in world space.
  expectNear(worldVertex(scene, 2), {1, 2, 0});
  const AnimationPlayer player(scene);
  ASSERT_EQ(player.deformedMeshes().size(), 1u);
  player.pose(scene, 0, 1.0f);
  // Joint 1's matrix is T(0,1,0) R90 T(0,-1,0): (1,2,0) -> (-1,2,0); (0,2,0) -> (-1,1,0), blended half with
  // joint 0's identity: (-0.5,1.5,0). Vertices 0 and 1 stay.
  expectNear(worldVertex(scene, 0), {0, 0, 0});
  expectNear(worldVertex(scene, 1), {1, 0, 0});
  expectNear(worldVertex(scene, 2), {-1, 2, 0});
  expectNear(worldVertex(scene, 3), {-0.5f, 1.5f, 0});
  // Halfway: 45 degrees.
  player.pose(scene, 0, 0.5f);
  expectNear(worldVertex(scene, 2), {kSqrtHalf - kSqrtHalf, 1 + kSqrtHalf + kSqrtHalf, 0});
  player.pose(scene, -1, 0.0f);
  expectNear(worldVertex(scene, 3), {0, 2, 0});
}

TEST(GltfSkins, ASceneFilePlacingASkinnedModelTwiceDeformsEachPlacement) {
  TempFolder folder;
  skinnedQuad().write(folder);
  const std::string path = folder.write("scene.json", R"({"models": [{"file": "deformed.gltf"},
      {"file": "deformed.gltf", "transform": {"translate": [0, 0, -3]}}]})");
  Scene scene = loadScene(path, SceneLoadOptions{});
  ASSERT_EQ(scene.animation.deformations.size(), 2u);
  ASSERT_EQ(scene.instances.size(), 2u);
  EXPECT_NE(scene.instances[0].meshId, scene.instances[1].meshId);  // loaded again: meshes of its own
  AnimationPlayer(scene).pose(scene, 0, 1.0f);
  for (size_t i = 0; i < 2; ++i) {
    const Instance& instance = scene.instances[i];
    expectNear(instance.objectToWorld.point(scene.meshes[instance.meshId].positions[2]),
               {-1, 2, i == 0 ? 0.0f : -3.0f});
  }
}

// A unit quad skinned with eight influences per vertex (JOINTS_0 / WEIGHTS_0 and JOINTS_1 / WEIGHTS_1) to eight
// joints: nodes 1-4 at the origin and nodes 5-8 at z = 1, 2, 3 and 4, all with identity inverse bind matrices, so
// a vertex moves by the weighted sum of its joints' heights. Vertex 0 follows joint 0; vertex 1 weighs each joint
// by 0.1 in the first set and 0.15 in the second (z += 1.5); vertex 2 by twice that, which normalisation over all
// eight brings back to vertex 1's weights; vertex 3 follows the eighth joint alone (z += 4). "Raise" moves the
// eighth joint from z = 4 to z = 6 over 1 s.
GltfFile eightInfluenceQuad() {
  GltfFile f;
  const int positions = f.floats({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, "VEC3");
  const int indices = f.add(std::vector<uint16_t>{0, 1, 2, 0, 2, 3}, "SCALAR", 5123, 1);
  const int joints0 = f.add(std::vector<uint8_t>{0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3}, "VEC4", 5121, 4);
  const int weights0 = f.floats({1, 0, 0, 0, 0.1f, 0.1f, 0.1f, 0.1f, 0.2f, 0.2f, 0.2f, 0.2f, 0, 0, 0, 0}, "VEC4");
  const int joints1 = f.add(std::vector<uint8_t>{4, 5, 6, 7, 4, 5, 6, 7, 4, 5, 6, 7, 4, 5, 6, 7}, "VEC4", 5121, 4);
  const int weights1 = f.floats({0, 0, 0, 0, 0.15f, 0.15f, 0.15f, 0.15f, 0.3f, 0.3f, 0.3f, 0.3f, 0, 0, 0, 1}, "VEC4");
  f.gltf["meshes"] = {{{"primitives",
                        {{{"attributes",
                           {{"POSITION", positions},
                            {"JOINTS_0", joints0},
                            {"WEIGHTS_0", weights0},
                            {"JOINTS_1", joints1},
                            {"WEIGHTS_1", weights1}}},
                          {"indices", indices}}}}}};
  f.gltf["skins"] = {{{"joints", {1, 2, 3, 4, 5, 6, 7, 8}}}};
  f.gltf["nodes"] = {{{"mesh", 0}, {"skin", 0}}};
  for (int joint = 0; joint < 8; ++joint)
    f.gltf["nodes"].push_back({{"translation", {0, 0, joint < 4 ? 0 : joint - 3}}});
  f.gltf["scenes"] = {{{"nodes", {0, 1, 2, 3, 4, 5, 6, 7, 8}}}};
  const int times = f.floats({0, 1}, "SCALAR");
  const int heights = f.floats({0, 0, 4, 0, 0, 6}, "VEC3");
  f.gltf["animations"] = {{{"name", "Raise"},
                           {"samplers", {{{"input", times}, {"output", heights}}}},
                           {"channels", {{{"sampler", 0}, {"target", {{"node", 8}, {"path", "translation"}}}}}}}};
  return f;
}

// The line loadGltf fails `file` with, or "(loaded)".
std::string loadError(GltfFile file) {
  TempFolder folder;
  LoadWarnings warnings;
  try {
    loadGltf(file.write(folder), warnings);
  } catch (const LoadError& e) {
    return e.what();
  }
  return "(loaded)";
}

TEST(GltfSkins, HostileSkinDataIsOneLineNamingThePlace) {
  {
    GltfFile file = skinnedQuad();
    file.gltf["skins"][0]["joints"] = {1};  // vertex 2 names joint 1 of a skin with one
    EXPECT_NE(loadError(file).find("meshes[0].primitives[0].attributes.JOINTS_0: vertex 2 names joint 1"),
              std::string::npos)
        << loadError(file);
  }
  {
    GltfFile file = skinnedQuad();
    file.gltf["skins"][0]["inverseBindMatrices"] =
        file.floats({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}, "MAT4");
    EXPECT_NE(loadError(file).find("skins[0].inverseBindMatrices: 1 matrices for 2 joints"), std::string::npos)
        << loadError(file);
  }
  {
    GltfFile file = eightInfluenceQuad();
    file.gltf["skins"][0]["joints"] = {1, 2, 3, 4, 5, 6, 7};  // vertex 1 weighs joint 7 in its second set
    EXPECT_NE(loadError(file).find("meshes[0].primitives[0].attributes.JOINTS_1: vertex 1 names joint 7"),
              std::string::npos)
        << loadError(file);
  }
  {
    GltfFile file = skinnedQuad();
    file.gltf["skins"][0]["joints"] = {1, 7};
    TempFolder folder;
    LoadWarnings warnings;
    const Scene scene = loadGltf(file.write(folder), warnings);  // a joint that is no node: a warning
    EXPECT_TRUE(scene.animation.deformations.empty());
    ASSERT_FALSE(warnings.messages.empty());
    EXPECT_NE(warnings.messages[0].find("skins[0].joints: node 7 is not in the scene"), std::string::npos);
  }
}

TEST(GltfSkins, TheFifthToEighthInfluencesCountAndAllEightAreNormalisedTogether) {
  TempFolder folder;
  LoadWarnings warnings;
  Scene scene = loadGltf(eightInfluenceQuad().write(folder), warnings);
  EXPECT_TRUE(warnings.messages.empty()) << warnings.messages[0];
  ASSERT_EQ(scene.animation.deformations.size(), 1u);
  EXPECT_EQ(scene.animation.deformations[0].influences, 8u);
  // The rest pose, as loaded.
  expectNear(worldVertex(scene, 0), {0, 0, 0});
  expectNear(worldVertex(scene, 1), {1, 0, 1.5f});
  expectNear(worldVertex(scene, 2), {1, 1, 1.5f});
  expectNear(worldVertex(scene, 3), {0, 1, 4});
  // The eighth joint raised by 2: vertex 1 and 2 follow it by their weight 0.15, vertex 3 wholly.
  AnimationPlayer(scene).pose(scene, 0, 1.0f);
  expectNear(worldVertex(scene, 0), {0, 0, 0});
  expectNear(worldVertex(scene, 1), {1, 0, 1.8f});
  expectNear(worldVertex(scene, 2), {1, 1, 1.8f});
  expectNear(worldVertex(scene, 3), {0, 1, 6});
}

TEST(GltfSkins, AMeshWithoutASecondSetKeepsFourInfluences) {
  TempFolder folder;
  Scene scene = loadScene(skinnedQuad().write(folder), SceneLoadOptions{});
  ASSERT_EQ(scene.animation.deformations.size(), 1u);
  EXPECT_EQ(scene.animation.deformations[0].influences, 4u);
  EXPECT_EQ(scene.animation.deformations[0].jointWeights.size(), 16u);
}

TEST(GltfSkins, TheSceneCacheKeepsEightInfluences) {
  TempFolder folder;
  const test::GltfCacheRoundTrip cache(folder, eightInfluenceQuad().write(folder));
  const Scene& scene = cache.loaded();
  CachedScene read;
  ASSERT_EQ(cache.writeAndRead(scene, read), SceneCacheRead::Hit);
  Scene posed = read.scene;
  AnimationPlayer(posed).pose(posed, 0, 1.0f);
  expectNear(worldVertex(posed, 3), {0, 1, 6});
  expectNear(worldVertex(posed, 2), {1, 1, 1.8f});

  Scene broken = scene;
  broken.animation.deformations[0].influences = 4;  // twice the joints and weights it claims
  EXPECT_EQ(cache.refusal(broken), "a mesh deformation has not four or eight joints and weights per vertex");
}

// A quad (z = 0) with one morph target that lifts vertex 2 by 1 in z and tilts its normal, whose weight "Lift"
// animates from 0 to 1 over 1 s.
GltfFile morphedQuad() {
  GltfFile f;
  const int positions = f.floats({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, "VEC3");
  const int normals = f.floats({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3");
  const int lift = f.floats({0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0}, "VEC3");
  const int tilt = f.floats({0, 0, 0, 0, 0, 0, 1, 0, -1, 0, 0, 0}, "VEC3");
  const int indices = f.add(std::vector<uint16_t>{0, 1, 2, 0, 2, 3}, "SCALAR", 5123, 1);
  f.gltf["meshes"] = {{{"primitives",
                        {{{"attributes", {{"POSITION", positions}, {"NORMAL", normals}}},
                          {"targets", {{{"POSITION", lift}, {"NORMAL", tilt}}}},
                          {"indices", indices}}}},
                       {"weights", {0}}}};
  f.gltf["nodes"] = {{{"mesh", 0}, {"translation", {0, 0, -2}}}};
  f.gltf["scenes"] = {{{"nodes", {0}}}};
  const int times = f.floats({0, 1}, "SCALAR");
  const int weights = f.floats({0, 1}, "SCALAR");
  f.gltf["animations"] = {{{"name", "Lift"},
                           {"samplers", {{{"input", times}, {"output", weights}}}},
                           {"channels", {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "weights"}}}}}}}};
  return f;
}

TEST(GltfMorphTargets, OneTargetBlendsByItsAnimatedWeight) {
  TempFolder folder;
  Scene scene = loadScene(morphedQuad().write(folder), SceneLoadOptions{});
  ASSERT_EQ(scene.animation.deformations.size(), 1u);
  EXPECT_EQ(scene.animation.deformations[0].targetCount, 1u);
  expectNear(worldVertex(scene, 2), {1, 1, -2});
  const AnimationPlayer player(scene);
  player.pose(scene, 0, 0.25f);
  expectNear(worldVertex(scene, 2), {1, 1, -1.75f});
  const Vec3 tilted = normalize(Vec3{0.25f, 0, 0.75f});
  expectNear(scene.meshes[0].normals[2], tilted);
  expectNear(scene.meshes[0].normals[0], {0, 0, 1});
  player.pose(scene, 0, 1.0f);
  expectNear(worldVertex(scene, 2), {1, 1, -1});
  expectNear(worldVertex(scene, 1), {1, 0, -2});
}

TEST(GltfMorphTargets, StaticNodeWeightsShapeTheMeshWithoutAnimation) {
  TempFolder folder;
  GltfFile file = morphedQuad();
  file.gltf.erase("animations");
  file.gltf["nodes"][0]["weights"] = {0.5};  // the node's weights win over the mesh's
  LoadWarnings warnings;
  const Scene scene = loadGltf(file.write(folder), warnings);
  EXPECT_TRUE(scene.animation.empty());
  EXPECT_TRUE(scene.animation.deformations.empty());  // applied once, nothing left to animate
  expectNear(worldVertex(scene, 2), {1, 1, -1.5f});
}

// A morph target's TANGENT deltas turn the tangents' directions and keep their handedness.
TEST(GltfMorphTargets, TangentDeltasTurnTangentsAndKeepTheirHandedness) {
  TempFolder folder;
  GltfFile file = morphedQuad();
  auto& primitive = file.gltf["meshes"][0]["primitives"][0];
  primitive["attributes"]["TANGENT"] = file.floats({1, 0, 0, -1, 1, 0, 0, -1, 1, 0, 0, -1, 1, 0, 0, -1}, "VEC4");
  primitive["targets"][0]["TANGENT"] = file.floats({0, 0, 0, 0, 0, 0, -1, 1, 0, 0, 0, 0}, "VEC3");
  LoadWarnings warnings;
  Scene scene = loadGltf(file.write(folder), warnings);
  EXPECT_TRUE(warnings.messages.empty()) << warnings.messages[0];
  ASSERT_EQ(scene.animation.deformations.size(), 1u);
  ASSERT_EQ(scene.meshes[0].tangents.size(), 4u);
  const AnimationPlayer player(scene);
  player.pose(scene, 0, 0.5f);
  const Vec4 turned = scene.meshes[0].tangents[2];
  expectNear(Vec3{turned.x, turned.y, turned.z}, {kSqrtHalf, kSqrtHalf, 0});
  EXPECT_EQ(turned.w, -1.0f);
  const Vec4 kept = scene.meshes[0].tangents[0];
  expectNear(Vec3{kept.x, kept.y, kept.z}, {1, 0, 0});
  player.pose(scene, 0, 1.0f);
  expectNear(Vec3{scene.meshes[0].tangents[2].x, scene.meshes[0].tangents[2].y, scene.meshes[0].tangents[2].z},
             {0, 1, 0});
}

// Morph targets without accessors, or nodes that each deform a copy of one mesh, cost little in the file but a
// vertex each here: past 2^24 such vertices the load stops with one line.
TEST(GltfMorphTargets, TooManyDeformedVerticesAreRefusedWithOneLine) {
  auto bigMesh = [](json targets) {
    GltfFile f;
    const int positions = f.floats(std::vector<float>(3 * 16384, 0.0f), "VEC3");
    f.gltf["meshes"] = {{{"primitives", {{{"attributes", {{"POSITION", positions}}}, {"targets", targets}}}}}};
    f.gltf["nodes"] = {{{"mesh", 0}}};
    f.gltf["scenes"] = {{{"nodes", {0}}}};
    return f;
  };
  const std::string limit = "skinned and morphed meshes of more than 16777216 vertices in all";
  GltfFile emptyTargets = bigMesh(json::array());
  for (int t = 0; t < 1024; ++t) emptyTargets.gltf["meshes"][0]["primitives"][0]["targets"].push_back(json::object());
  EXPECT_NE(loadError(emptyTargets).find("nodes[0]: " + limit), std::string::npos) << loadError(emptyTargets);

  GltfFile copies = bigMesh(json::array({json::object()}));
  for (int n = 1; n < 600; ++n) {
    copies.gltf["nodes"].push_back({{"mesh", 0}});
    copies.gltf["scenes"][0]["nodes"].push_back(n);
  }
  EXPECT_NE(loadError(copies).find(limit), std::string::npos) << loadError(copies);
}

// A morph target's delta that is not finite is refused in one line naming it (a fuzzing input's POSITION deltas
// shared a bufferView with normals that held not-a-number, which the player then failed to pose).
TEST(GltfMorphTargets, NonFiniteDeltasAreOneLineNamingTheTarget) {
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  for (const char* attribute : {"POSITION", "NORMAL"}) {
    GltfFile file = morphedQuad();
    file.gltf["meshes"][0]["primitives"][0]["targets"][0][attribute] =
        file.floats({0, 0, 0, 0, 0, 0, 0, nan, 1, 0, inf, 0}, "VEC3");
    EXPECT_NE(loadError(file).find("meshes[0].primitives[0].targets[0]." + std::string(attribute) +
                                   ": value 2 is not finite"),
              std::string::npos)
        << loadError(file);
  }
}

TEST(GltfMorphTargets, TheSceneCacheKeepsDeformations) {
  TempFolder folder;
  const test::GltfCacheRoundTrip cache(folder, skinnedQuad().write(folder));
  const Scene& scene = cache.loaded();
  CachedScene read;
  ASSERT_EQ(cache.writeAndRead(scene, read), SceneCacheRead::Hit);
  ASSERT_EQ(read.scene.animation.deformations.size(), 1u);
  Scene posed = read.scene;
  AnimationPlayer(posed).pose(posed, 0, 1.0f);
  expectNear(worldVertex(posed, 2), {-1, 2, 0});

  Scene broken = scene;
  broken.animation.deformations[0].joints[9] = 5;
  EXPECT_EQ(cache.refusal(broken), "a mesh deformation refers to a missing joint");
}

// A morphed mesh whose normals are not all finite (the rest shape the player poses from holds them too): the
// scene cache, which holds finite attributes only, stores it once the load has repaired them, and the scene read
// back is the one loaded.
TEST(GltfMorphTargets, AMeshWithNonFiniteNormalsIsCachedRepaired) {
  TempFolder folder;
  GltfFile file = morphedQuad();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  file.gltf["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] =
      file.floats({nan, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3");
  const std::string path = file.write(folder);
  SceneLoadOptions options;
  options.cache = {true, folder.file("cache")};
  const Scene fresh = loadScene(path, options);
  CachedScene stored;
  EXPECT_EQ(readSceneCache(sceneCacheFile(folder.file("cache"), path), path, stored), SceneCacheRead::Hit);
  const Scene cached = loadScene(path, options);
  for (const Scene* scene : {&fresh, &cached}) {
    ASSERT_EQ(scene->animation.deformations.size(), 1u);
    expectNear(scene->meshes[0].normals[0], {0, 0, 0});
    expectNear(scene->animation.deformations[0].normals[0], {0, 0, 0});
    expectNear(scene->animation.deformations[0].normals[1], {0, 0, 1});
  }
  Scene posed = cached;
  AnimationPlayer(posed).pose(posed, 0, 0.25f);
  expectNear(posed.meshes[0].normals[2], normalize(Vec3{0.25f, 0, 0.75f}));
}

// Renders of the bending quad: setDeformedMeshes gives the image of a full setScene of the posed scene, and the
// image changes between the times.
TEST(GltfSkins, RendersAtTwoTimesDifferAndMatchAFullRebuild) {
  TempFolder folder;
  Scene scene = loadScene(skinnedQuad().write(folder), SceneLoadOptions{});
  const AnimationPlayer player(scene);
  RenderSettings settings;
  settings.width = 40;
  settings.height = 30;
  settings.seed = 9;
  const Camera camera = scene.camera.toCamera(40.0f / 30.0f);
  auto render = [&](CpuBackend& backend) {
    backend.setSettings(settings);
    backend.setCamera(camera);
    backend.render(1);
    return backend.readImage();
  };
  CpuBackend animated;
  animated.setScene(scene);
  const Image atRest = render(animated);
  player.pose(scene, 0, 1.0f);
  animated.setDeformedMeshes(scene, player.deformedMeshes());
  const Image bent = render(animated);
  CpuBackend rebuilt;
  rebuilt.setScene(scene);
  const Image expected = render(rebuilt);
  test::expectRebuiltImageThatChanged(bent, expected, atRest, 5.0);
}

}  // namespace
}  // namespace candela
