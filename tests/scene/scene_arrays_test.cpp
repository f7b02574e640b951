// The list of the scene's flat arrays (kernel/scene_arrays.h) drives their mirrors: each check here is generated
// from the list, so an array added to it is checked without a change here.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <memory>
#include <vector>

#include "kernel/scene_arrays.h"
#include "scene/cache/binary_stream.h"
#include "scene/cache/scene_serialization.h"
#include "scene/flat_scene.h"

namespace candela {
namespace {

template <class T>
bool sameBytes(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

// `n` elements whose bytes run on from `first`, so that no two elements nor two arrays filled from different
// starts are alike.
template <class T>
std::vector<T> distinctElements(size_t n, uint8_t first) {
  std::vector<T> values(n);
  std::vector<uint8_t> bytes(n * sizeof(T));
  for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = uint8_t(first + i);
  std::memcpy(values.data(), bytes.data(), bytes.size());
  return values;
}

void expectCount(const SceneView&, std::nullptr_t, size_t, const char*) {}
void expectCount(const SceneView& view, uint32_t SceneView::*count, size_t size, const char* member) {
  EXPECT_EQ(view.*count, size) << member;
}

TEST(SceneArrays, TheHostViewPointsAtEveryArrayAndHoldsTheCountsTheListNames) {
  FlatScene flat;
  size_t n = 1;
#define CANDELA_FILL(Type, member, upload, count, description) flat.member.resize(n++);
  CANDELA_SCENE_ARRAYS(CANDELA_FILL)
#undef CANDELA_FILL
  const SceneView view = flat.hostView();
#define CANDELA_EXPECT_POINTED_AT(Type, member, upload, count, description) \
  EXPECT_EQ(view.member, flat.member.data()) << #member;                    \
  expectCount(view, CANDELA_SCENE_ARRAY_COUNT_FIELD(count), flat.member.size(), #member);
  CANDELA_SCENE_ARRAYS(CANDELA_EXPECT_POINTED_AT)
#undef CANDELA_EXPECT_POINTED_AT
}

TEST(SceneArrays, TheHostViewOfAnEmptyArrayIsNull) {
  FlatScene flat;
#define CANDELA_RESERVE(Type, member, upload, count, description) flat.member.reserve(4);
  CANDELA_SCENE_ARRAYS(CANDELA_RESERVE)
#undef CANDELA_RESERVE
  const SceneView view = flat.hostView();
#define CANDELA_EXPECT_NULL(Type, member, upload, count, description) \
  EXPECT_EQ(view.member, nullptr) << #member;                         \
  expectCount(view, CANDELA_SCENE_ARRAY_COUNT_FIELD(count), 0, #member);
  CANDELA_SCENE_ARRAYS(CANDELA_EXPECT_NULL)
#undef CANDELA_EXPECT_NULL
}

// Every per-mesh array, filled with bytes no two arrays share, comes back from the scene cache's serializer as it
// went in, mesh by mesh.
TEST(SceneArrays, EveryPerMeshArrayRoundTripsThroughTheSceneCache) {
  Scene scene;
  uint8_t first = 1;
  for (size_t k = 0; k < 2; ++k) {
    Mesh mesh;
    mesh.name = "mesh" + std::to_string(k);
#define CANDELA_FILL(Type, member, upload, count, description) \
  mesh.member = distinctElements<Type>(3 + k, first);          \
  first = uint8_t(first + 37);
    CANDELA_MESH_ARRAYS(CANDELA_FILL)
#undef CANDELA_FILL
    scene.meshes.push_back(mesh);
  }
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::tmpfile(), &std::fclose);
  ASSERT_TRUE(file);
  {
    BinaryWriter out(file.get());
    writeScene(out, scene);
    out.finish();
    ASSERT_TRUE(out.ok());
  }
  const long size = std::ftell(file.get());
  std::rewind(file.get());
  BinaryReader in(file.get(), uint64_t(size));
  Scene read;
  ASSERT_TRUE(readScene(in, read));
  EXPECT_TRUE(in.checksumMatches());
  ASSERT_EQ(read.meshes.size(), scene.meshes.size());
  for (size_t k = 0; k < scene.meshes.size(); ++k) {
    EXPECT_EQ(read.meshes[k].name, scene.meshes[k].name);
#define CANDELA_EXPECT_SAME(Type, member, upload, count, description) \
  EXPECT_TRUE(sameBytes(read.meshes[k].member, scene.meshes[k].member)) << #member << " of mesh " << k;
    CANDELA_MESH_ARRAYS(CANDELA_EXPECT_SAME)
#undef CANDELA_EXPECT_SAME
  }
}

// A triangle with every per-mesh array given, its vertices and its material numbered from `k`.
Mesh fullTriangle(uint32_t k) {
  const float f = float(k);
  Mesh m;
  m.name = "triangle" + std::to_string(k);
  m.positions = {{f, 0, 0}, {f + 1, 0, 0}, {f, 1, 0}};
  m.normals = {{0, 0, 1}, {0, 0.6f, 0.8f}, {0, 0.8f, 0.6f}};
  m.uvs = {{f, 0}, {1, f}, {0, 1}};
  m.tangents = {{1, 0, 0, 1}, {1, 0, 0, -1}, {0, 1, 0, 1}};
  m.colors = {{f, 0.5f, 0.25f}, {0.125f, f, 1}, {1, 1, f}};
  m.indices = {0, 2, 1};
  m.triangleMaterials = {k};
  return m;
}

// A ribbon (a mesh of curves, which holds no triangles) with every curve array given, numbered from `k`.
Mesh fullRibbon(uint32_t k) {
  const float f = float(k);
  Mesh m;
  m.name = "ribbon" + std::to_string(k);
  m.curveVertices = {{f, 0, 0, 0.1f}, {f + 1, 1, 0, 0.2f}, {f + 2, -1, 0, 0.3f}, {f + 3, 0, 0, 0.4f}};
  m.curveNormals = {{0, 0, 1}, {0, 0.6f, 0.8f}, {0, 0.8f, 0.6f}, {0, 1, 0}};
  m.curveSegments = {{0, k, CurveType::Ribbon}};
  return m;
}

// FlatScene::build puts each mesh's arrays back to back, array by array.
TEST(SceneArrays, TheFlatSceneConcatenatesEveryPerMeshArray) {
  Scene scene;
  scene.materials = {Material{}, Material{}};
  scene.meshes = {fullTriangle(0), fullRibbon(0), fullTriangle(1), fullRibbon(1)};
  scene.instances = {{0, Affine3x4{}}, {1, Affine3x4{}}, {2, Affine3x4{}}, {3, Affine3x4{}}};
  const FlatScene flat = FlatScene::build(scene);
#define CANDELA_EXPECT_CONCATENATED(Type, member, upload, count, description)                             \
  {                                                                                                       \
    std::vector<Type> expected;                                                                           \
    for (const Mesh& m : scene.meshes) expected.insert(expected.end(), m.member.begin(), m.member.end()); \
    ASSERT_FALSE(expected.empty()) << "no mesh here gives " #member;                                      \
    EXPECT_TRUE(sameBytes(flat.member, expected)) << #member;                                             \
  }
  CANDELA_MESH_ARRAYS(CANDELA_EXPECT_CONCATENATED)
#undef CANDELA_EXPECT_CONCATENATED
}

}  // namespace
}  // namespace candela
