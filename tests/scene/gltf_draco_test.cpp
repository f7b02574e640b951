// KHR_draco_mesh_compression: meshes encoded here with Draco's own encoder load as their uncompressed twins do.
#include <gtest/gtest.h>

#include <draco/compression/encode.h>
#include <draco/mesh/triangle_soup_mesh_builder.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cstring>
#include <tuple>

#include "io/available_memory.h"
#include "io/load_budget.h"
#include "scene/loaders/gltf/gltf_accessors.h"
#include "scene/loaders/gltf/gltf_draco.h"
#include "scene/loaders/gltf/gltf_loader.h"
#include "support/glb_file.h"

namespace candela {
namespace {

using nlohmann::json;

// A 3x3 grid of vertices over z = 0 made of 8 triangles, each corner with a position, normal, uv and colour.
struct Corner {
  std::array<float, 3> position, normal;
  std::array<float, 2> uv;
  std::array<uint8_t, 4> colour;
};
std::vector<Corner> gridCorners() {
  auto corner = [](int i, int j) {
    const float x = float(i) * 0.5f, y = float(j) * 0.5f;
    return Corner{
        {x, y, 0.1f * float(i * j)}, {0.0f, 0.6f, 0.8f}, {x, 1.0f - y}, {uint8_t(40 * i), uint8_t(90 * j), 200, 255}};
  };
  std::vector<Corner> corners;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i)
      for (auto [a, b, c] : {std::array{std::pair{i, j}, std::pair{i + 1, j}, std::pair{i + 1, j + 1}},
                             std::array{std::pair{i, j}, std::pair{i + 1, j + 1}, std::pair{i, j + 1}}}) {
        corners.push_back(corner(a.first, a.second));
        corners.push_back(corner(b.first, b.second));
        corners.push_back(corner(c.first, c.second));
      }
  return corners;
}

// Draco ids of the encoded attributes.
struct DracoIds {
  int position, normal, uv, colour;
};

std::vector<uint8_t> encodeWithDraco(const std::vector<Corner>& corners, DracoIds& ids) {
  draco::TriangleSoupMeshBuilder builder;
  const int faces = int(corners.size() / 3);
  builder.Start(faces);
  const int position = builder.AddAttribute(draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT32);
  const int normal = builder.AddAttribute(draco::GeometryAttribute::NORMAL, 3, draco::DT_FLOAT32);
  const int uv = builder.AddAttribute(draco::GeometryAttribute::TEX_COORD, 2, draco::DT_FLOAT32);
  const int colour = builder.AddAttribute(draco::GeometryAttribute::COLOR, 4, draco::DT_UINT8, true);
  for (int f = 0; f < faces; ++f) {
    const Corner* c = &corners[size_t(3 * f)];
    builder.SetAttributeValuesForFace(position, draco::FaceIndex(f), c[0].position.data(), c[1].position.data(),
                                      c[2].position.data());
    builder.SetAttributeValuesForFace(normal, draco::FaceIndex(f), c[0].normal.data(), c[1].normal.data(),
                                      c[2].normal.data());
    builder.SetAttributeValuesForFace(uv, draco::FaceIndex(f), c[0].uv.data(), c[1].uv.data(), c[2].uv.data());
    builder.SetAttributeValuesForFace(colour, draco::FaceIndex(f), c[0].colour.data(), c[1].colour.data(),
                                      c[2].colour.data());
  }
  std::unique_ptr<draco::Mesh> mesh = builder.Finalize();
  EXPECT_TRUE(mesh);
  ids = {int(mesh->attribute(position)->unique_id()), int(mesh->attribute(normal)->unique_id()),
         int(mesh->attribute(uv)->unique_id()), int(mesh->attribute(colour)->unique_id())};
  draco::Encoder encoder;  // no quantisation: the values come back exactly, in Draco's own vertex order
  draco::EncoderBuffer out;
  const draco::Status status = encoder.EncodeMeshToBuffer(*mesh, &out);
  EXPECT_TRUE(status.ok()) << status.error_msg_string();
  return std::vector<uint8_t>(out.data(), out.data() + out.size());
}

json accessors(size_t vertices, size_t indices) {
  return {{{"componentType", 5126}, {"count", vertices}, {"type", "VEC3"}},
          {{"componentType", 5126}, {"count", vertices}, {"type", "VEC3"}},
          {{"componentType", 5126}, {"count", vertices}, {"type", "VEC2"}},
          {{"componentType", 5121}, {"normalized", true}, {"count", vertices}, {"type", "VEC4"}},
          {{"componentType", 5123}, {"count", indices}, {"type", "SCALAR"}}};
}

json meshOf(const json& extensions) {
  json primitive = {{"attributes", {{"POSITION", 0}, {"NORMAL", 1}, {"TEXCOORD_0", 2}, {"COLOR_0", 3}}},
                    {"indices", 4}};
  if (!extensions.is_null()) primitive["extensions"] = extensions;
  return {{"primitives", {primitive}}};
}

// The corners as a plain glTF would store them: one vertex per corner, attributes one after another.
std::vector<uint8_t> uncompressedGlb(const std::vector<Corner>& corners) {
  std::vector<uint8_t> bin;
  auto add = [&](const void* p, size_t n) {
    bin.insert(bin.end(), static_cast<const uint8_t*>(p), static_cast<const uint8_t*>(p) + n);
  };
  for (const Corner& c : corners) add(c.position.data(), 12);
  for (const Corner& c : corners) add(c.normal.data(), 12);
  for (const Corner& c : corners) add(c.uv.data(), 8);
  for (const Corner& c : corners) add(c.colour.data(), 4);
  for (uint16_t i = 0; i < corners.size(); ++i) add(&i, 2);
  const size_t n = corners.size();
  json views = json::array();
  size_t offset = 0;
  for (size_t length : {12 * n, 12 * n, 8 * n, 4 * n, 2 * n}) {
    views.push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", length}});
    offset += length;
  }
  json a = accessors(n, n);
  for (size_t i = 0; i < a.size(); ++i) a[i]["bufferView"] = i;
  json g = {{"asset", {{"version", "2.0"}}}, {"buffers", {{{"byteLength", bin.size()}}}},
            {"bufferViews", views},          {"accessors", a},
            {"meshes", {meshOf(nullptr)}},   {"nodes", {{{"mesh", 0}}}},
            {"scenes", {{{"nodes", {0}}}}}};
  return test::glbFile(g, bin);
}

// A glTF whose one primitive is `draco`, as KHR_draco_mesh_compression stores it: accessors without bufferViews.
std::vector<uint8_t> dracoGlb(const std::vector<uint8_t>& draco, const DracoIds& ids, size_t vertices, size_t indices) {
  json extension = {
      {"KHR_draco_mesh_compression",
       {{"bufferView", 0},
        {"attributes",
         {{"POSITION", ids.position}, {"NORMAL", ids.normal}, {"TEXCOORD_0", ids.uv}, {"COLOR_0", ids.colour}}}}}};
  json g = {{"asset", {{"version", "2.0"}}},
            {"extensionsUsed", {"KHR_draco_mesh_compression"}},
            {"extensionsRequired", {"KHR_draco_mesh_compression"}},
            {"buffers", {{{"byteLength", (draco.size() + 3) / 4 * 4}}}},
            {"bufferViews", {{{"buffer", 0}, {"byteLength", draco.size()}}}},
            {"accessors", accessors(vertices, indices)},
            {"meshes", {meshOf(extension)}},
            {"nodes", {{{"mesh", 0}}}},
            {"scenes", {{{"nodes", {0}}}}}};
  return test::glbFile(g, draco);
}

Scene load(const std::vector<uint8_t>& bytes) {
  LoadWarnings warnings;
  Scene scene = loadGltfBytes("test.glb", bytes.data(), bytes.size(), warnings);
  EXPECT_TRUE(warnings.messages.empty()) << warnings.messages[0];
  validateScene(scene);
  return scene;
}

std::string errorOf(const std::vector<uint8_t>& bytes) {
  LoadWarnings warnings;
  try {
    loadGltfBytes("test.glb", bytes.data(), bytes.size(), warnings);
  } catch (const LoadError& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
    return e.what();
  }
  ADD_FAILURE() << "expected a LoadError";
  return {};
}

// The mesh's triangles, each as its corners' attributes starting from its smallest corner (winding kept), sorted:
// equal for meshes that differ only in the order of their vertices and triangles.
using CornerKey = std::tuple<float, float, float, float, float, float, float, float, float, float, float>;
std::vector<std::array<CornerKey, 3>> triangles(const Mesh& m) {
  std::vector<std::array<CornerKey, 3>> out;
  for (size_t t = 0; t < m.triangleCount(); ++t) {
    std::array<CornerKey, 3> tri;
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = m.indices[3 * t + size_t(k)];
      const Vec3 p = m.positions[v], n = m.normals[v], c = m.colors[v];
      const Vec2 uv = m.uvs[v];
      tri[size_t(k)] = {p.x, p.y, p.z, n.x, n.y, n.z, uv.x, uv.y, c.x, c.y, c.z};
    }
    std::rotate(tri.begin(), std::min_element(tri.begin(), tri.end()), tri.end());
    out.push_back(tri);
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(GltfDraco, DecodesAsTheUncompressedMesh) {
  const std::vector<Corner> corners = gridCorners();
  DracoIds ids;
  const std::vector<uint8_t> draco = encodeWithDraco(corners, ids);
  const Scene plain = load(uncompressedGlb(corners));
  // Draco welds the corners into the grid's 9 vertices.
  const Scene compressed = load(dracoGlb(draco, ids, 9, corners.size()));
  ASSERT_EQ(compressed.meshes.size(), 1u);
  const Mesh& m = compressed.meshes[0];
  EXPECT_EQ(m.positions.size(), 9u);
  EXPECT_EQ(m.triangleCount(), 8u);
  EXPECT_EQ(triangles(m), triangles(plain.meshes[0]));
}

// Primitives that name the same compressed bytes (through one bufferView or several) are decoded once: their
// meshes become one mesh of the scene, instanced.
TEST(GltfDraco, PrimitivesNamingTheSameBytesAreDecodedOnceAndInstanced) {
  const std::vector<Corner> corners = gridCorners();
  DracoIds ids;
  const std::vector<uint8_t> draco = encodeWithDraco(corners, ids);
  const std::vector<uint8_t> one = dracoGlb(draco, ids, 9, corners.size());
  json g = json::parse(one.begin() + 20, one.begin() + 20 + *reinterpret_cast<const uint32_t*>(&one[12]));
  g["bufferViews"].push_back(g["bufferViews"][0]);
  for (int m = 1; m < 100; ++m) {
    json mesh = g["meshes"][0];
    mesh["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]["bufferView"] = m % 2;
    g["meshes"].push_back(mesh);
    g["nodes"].push_back({{"mesh", m}, {"translation", {2 * m, 0, 0}}});
    g["scenes"][0]["nodes"].push_back(m);
  }
  const Scene s = load(test::glbFile(g, draco));
  ASSERT_EQ(s.meshes.size(), 1u);
  EXPECT_EQ(s.meshes[0].positions.size(), 9u);
  EXPECT_EQ(s.instances.size(), 100u);
}

TEST(GltfDraco, CorruptDataIsRefusedNamingThePrimitive) {
  const std::vector<Corner> corners = gridCorners();
  DracoIds ids;
  std::vector<uint8_t> draco = encodeWithDraco(corners, ids);
  const std::string where = "test.glb: meshes[0].primitives[0].extensions.KHR_draco_mesh_compression";

  std::vector<uint8_t> truncated(draco.begin(), draco.begin() + std::ptrdiff_t(draco.size() / 2));
  std::string e = errorOf(dracoGlb(truncated, ids, 9, 24));
  EXPECT_EQ(e.rfind(where + ": the Draco data cannot be decoded", 0), 0u) << e;

  std::vector<uint8_t> garbage(draco.size(), 0xAB);
  e = errorOf(dracoGlb(garbage, ids, 9, 24));
  EXPECT_EQ(e.rfind(where + ": the Draco data cannot be decoded", 0), 0u) << e;

  DracoIds missing = ids;
  missing.normal = 77;
  e = errorOf(dracoGlb(draco, missing, 9, 24));
  EXPECT_EQ(e, where + ".attributes.NORMAL: the Draco data have no attribute with this id") << e;

  // A colour accessor of three components for Draco's four.
  std::vector<uint8_t> file = dracoGlb(draco, ids, 9, 24);
  const std::string text(file.begin(), file.end());
  const std::string vec4 = R"("normalized":true,"type":"VEC4")";
  ASSERT_NE(text.find(vec4), std::string::npos);
  std::string changed = text;
  changed.replace(changed.find(vec4), vec4.size(), R"("normalized":true,"type":"VEC3")");
  e = errorOf(std::vector<uint8_t>(changed.begin(), changed.end()));
  EXPECT_EQ(e, where + ".attributes.COLOR_0: the Draco attribute has 4 components, the accessor 3") << e;
}

// A .glb whose header or BIN chunk claims more bytes than the file has is refused in one line, not read beyond its
// end: the pass that rewrites a Draco file's JSON before tinygltf reads it must not make such a file look whole.
TEST(GltfDraco, LengthsBeyondTheFileAreRefused) {
  const std::vector<Corner> corners = gridCorners();
  DracoIds ids;
  const std::vector<uint8_t> file = dracoGlb(encodeWithDraco(corners, ids), ids, 9, 24);
  auto withWord = [&](size_t at, uint32_t value) {
    std::vector<uint8_t> changed = file;
    std::memcpy(changed.data() + at, &value, 4);
    return changed;
  };
  uint32_t jsonLength;
  std::memcpy(&jsonLength, file.data() + 12, 4);
  const size_t binAt = 20 + size_t(jsonLength);
  const std::string size = std::to_string(file.size());

  EXPECT_EQ(errorOf(withWord(8, uint32_t(file.size() + 8))), "test.glb: the .glb header says the file has " +
                                                                 std::to_string(file.size() + 8) + " bytes, it has " +
                                                                 size);
  const uint32_t binLength = uint32_t(file.size() - binAt - 8 + 4);
  EXPECT_EQ(errorOf(withWord(binAt, binLength)),
            "test.glb: the .glb's second chunk of " + std::to_string(binLength) + " bytes reaches beyond its end");
  EXPECT_EQ(errorOf(withWord(12, uint32_t(file.size()))),
            "test.glb: the .glb's JSON chunk of " + size + " bytes reaches beyond its end");
}

// Attributes the loader does not read itself (skin joints and weights) are decoded into their accessors' own
// component types, for whatever reads them.
// A grid of `cells` x `cells` squares, positions only, quantised: a few kilobytes that decode to megabytes.
std::vector<uint8_t> encodedGrid(int cells, int& positionId) {
  draco::TriangleSoupMeshBuilder builder;
  builder.Start(2 * cells * cells);
  const int position = builder.AddAttribute(draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT32);
  int face = 0;
  for (int j = 0; j < cells; ++j)
    for (int i = 0; i < cells; ++i) {
      auto p = [&](int di, int dj) { return std::array<float, 3>{float(i + di), float(j + dj), 0.0f}; };
      const auto a = p(0, 0), b = p(1, 0), c = p(1, 1), d = p(0, 1);
      builder.SetAttributeValuesForFace(position, draco::FaceIndex(face++), a.data(), b.data(), c.data());
      builder.SetAttributeValuesForFace(position, draco::FaceIndex(face++), a.data(), c.data(), d.data());
    }
  std::unique_ptr<draco::Mesh> mesh = builder.Finalize();
  EXPECT_TRUE(mesh);
  positionId = int(mesh->attribute(position)->unique_id());
  draco::Encoder encoder;
  encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, 11);
  draco::EncoderBuffer out;
  EXPECT_TRUE(encoder.EncodeMeshToBuffer(*mesh, &out).ok());
  return std::vector<uint8_t>(out.data(), out.data() + out.size());
}

// Each primitive's decoded buffer is charged to the load's budget before it is filled: a file of many different
// compressed meshes, each small, that together decode to more than the load may use is refused in one line
// naming the primitive; without the limit the same file loads.
TEST(GltfDraco, DecodedBytesBeyondTheLoadBudgetAreRefused) {
  int positionId = 0;
  const std::vector<uint8_t> grid = encodedGrid(200, positionId);
  const uint64_t decodedPerPrimitive = 201 * 201 * 12 + 2 * 200 * 200 * 12;  // at least: Draco may split points
  // The smallest limit (above what the test process holds) that leaves the load a budget of 4 MiB or more.
  uint64_t limit = uint64_t(16) << 20;
  for (;; limit *= 2) {
    setProcessMemoryLimit(limit);
    beginLoadBudget();
    if (loadMemoryLeft() >= (uint64_t(4) << 20)) break;
  }
  const int meshes = int(loadMemoryLeft() / decodedPerPrimitive) * 3 / 2 + 2;
  std::vector<uint8_t> bin;
  json views = json::array(), gltfMeshes = json::array(), nodes = json::array(), roots = json::array();
  for (int m = 0; m < meshes; ++m) {  // each mesh its own copy of the bytes: different streams, each decoded
    views.push_back({{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", grid.size()}});
    bin.insert(bin.end(), grid.begin(), grid.end());
    bin.resize((bin.size() + 3) / 4 * 4);
    json primitive = {
        {"attributes", {{"POSITION", 0}}},
        {"extensions",
         {{"KHR_draco_mesh_compression", {{"bufferView", m}, {"attributes", {{"POSITION", positionId}}}}}}}};
    gltfMeshes.push_back({{"primitives", {primitive}}});
    nodes.push_back({{"mesh", m}});
    roots.push_back(m);
  }
  json g = {{"asset", {{"version", "2.0"}}},
            {"extensionsUsed", {"KHR_draco_mesh_compression"}},
            {"extensionsRequired", {"KHR_draco_mesh_compression"}},
            {"buffers", {{{"byteLength", bin.size()}}}},
            {"bufferViews", views},
            {"accessors", {{{"componentType", 5126}, {"count", 201 * 201}, {"type", "VEC3"}}}},
            {"meshes", gltfMeshes},
            {"nodes", nodes},
            {"scenes", {{{"nodes", roots}}}}};
  const std::vector<uint8_t> file = test::glbFile(g, bin);
  const std::string error = errorOf(file);
  setProcessMemoryLimit(0);
  beginLoadBudget();
  EXPECT_NE(error.find("test.glb: meshes["), std::string::npos) << error;
  EXPECT_NE(error.find("].primitives[0] decoded from KHR_draco_mesh_compression needs about "), std::string::npos)
      << error;
  EXPECT_NE(error.find("--max-memory"), std::string::npos) << error;
  EXPECT_EQ(load(file).meshes.size(), size_t(meshes));
}

TEST(GltfDraco, JointsAndWeightsKeepTheirAccessorTypes) {
  draco::TriangleSoupMeshBuilder builder;
  builder.Start(1);
  const int position = builder.AddAttribute(draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT32);
  const int joints = builder.AddAttribute(draco::GeometryAttribute::GENERIC, 4, draco::DT_UINT8);
  const int weights = builder.AddAttribute(draco::GeometryAttribute::GENERIC, 4, draco::DT_FLOAT32);
  const float p[3][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const uint8_t j[3][4] = {{0, 1, 0, 0}, {2, 3, 0, 0}, {4, 5, 6, 0}};
  const float w[3][4] = {{1, 0, 0, 0}, {0.5f, 0.5f, 0, 0}, {0.25f, 0.25f, 0.5f, 0}};
  builder.SetAttributeValuesForFace(position, draco::FaceIndex(0), p[0], p[1], p[2]);
  builder.SetAttributeValuesForFace(joints, draco::FaceIndex(0), j[0], j[1], j[2]);
  builder.SetAttributeValuesForFace(weights, draco::FaceIndex(0), w[0], w[1], w[2]);
  std::unique_ptr<draco::Mesh> mesh = builder.Finalize();
  ASSERT_TRUE(mesh);
  draco::Encoder encoder;
  encoder.SetEncodingMethod(draco::MESH_SEQUENTIAL_ENCODING);  // keeps the vertex order
  draco::EncoderBuffer encoded;
  ASSERT_TRUE(encoder.EncodeMeshToBuffer(*mesh, &encoded).ok());

  tinygltf::Model model;
  model.buffers.resize(1);
  model.buffers[0].data.assign(encoded.data(), encoded.data() + encoded.size());
  model.bufferViews.resize(1);
  model.bufferViews[0].buffer = 0;
  model.bufferViews[0].byteLength = encoded.size();
  auto accessor = [](int componentType, int type) {
    tinygltf::Accessor a;
    a.componentType = componentType;
    a.type = type;
    a.count = 3;
    return a;
  };
  model.accessors = {accessor(TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3),
                     accessor(TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_TYPE_VEC4),
                     accessor(TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC4)};
  tinygltf::Primitive primitive;
  primitive.attributes = {{"POSITION", 0}, {"JOINTS_0", 1}, {"WEIGHTS_0", 2}};
  auto id = [&](int attribute) { return tinygltf::Value(int(mesh->attribute(attribute)->unique_id())); };
  tinygltf::Value::Object attributes{{"POSITION", id(position)}, {"JOINTS_0", id(joints)}, {"WEIGHTS_0", id(weights)}};
  tinygltf::Value::Object extension{{"bufferView", tinygltf::Value(0)}, {"attributes", tinygltf::Value(attributes)}};
  primitive.extensions["KHR_draco_mesh_compression"] = tinygltf::Value(extension);
  model.meshes.resize(1);
  model.meshes[0].primitives.push_back(primitive);

  GltfBufferCharge charge(GltfBufferList(""), "test.glb");
  decodeDracoPrimitives(model, "test.glb", charge);
  const tinygltf::Primitive& decoded = model.meshes[0].primitives[0];
  EXPECT_EQ(model.accessors[size_t(decoded.attributes.at("JOINTS_0"))].componentType,
            TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE);
  GltfAccessorReader reader(model, "test.glb");
  const std::vector<Vec4> jointValues = reader.readVec4(decoded.attributes.at("JOINTS_0"), "JOINTS_0");
  const std::vector<Vec4> weightValues = reader.readVec4(decoded.attributes.at("WEIGHTS_0"), "WEIGHTS_0");
  ASSERT_EQ(jointValues.size(), 3u);
  EXPECT_FLOAT_EQ(jointValues[2].y, 5.0f);
  EXPECT_FLOAT_EQ(jointValues[2].z, 6.0f);
  EXPECT_FLOAT_EQ(weightValues[1].x, 0.5f);
  EXPECT_FLOAT_EQ(weightValues[2].z, 0.5f);
  EXPECT_EQ(reader.readIndices(decoded.indices, "indices"), (std::vector<uint32_t>{0, 1, 2}));
}

}  // namespace
}  // namespace candela
