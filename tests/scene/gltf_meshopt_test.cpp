// EXT_meshopt_compression: bufferViews compressed with meshoptimizer's encoder, laid out as gltfpack writes them
// (the compressed bytes in the .glb's BIN chunk, the decoded views in a fallback buffer without data).
#include <gtest/gtest.h>
#include <meshoptimizer.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cstring>

#include "io/available_memory.h"
#include "io/load_budget.h"
#include "io/load_diagnostics.h"
#include "scene/loaders/gltf/gltf_loader.h"
#include "support/glb_file.h"

namespace candela {
namespace {

using nlohmann::json;

constexpr std::array<float, 12> kPositions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
constexpr std::array<unsigned, 6> kIndices = {0, 1, 2, 2, 1, 3};

// A quad of two triangles: positions (4 x 12 bytes) and 16-bit indices compressed into the BIN chunk.
struct CompressedQuad {
  json gltf;
  std::vector<uint8_t> bin;
};

CompressedQuad compressedQuad() {
  std::vector<uint8_t> vertices(meshopt_encodeVertexBufferBound(4, 12));
  vertices.resize(meshopt_encodeVertexBuffer(vertices.data(), vertices.size(), kPositions.data(), 4, 12));
  std::vector<uint8_t> indices(meshopt_encodeIndexBufferBound(6, 4));
  indices.resize(meshopt_encodeIndexBuffer(indices.data(), indices.size(), kIndices.data(), 6));
  std::vector<uint8_t> bin = vertices;
  bin.resize((bin.size() + 3) / 4 * 4, 0);
  const size_t indicesAt = bin.size();
  bin.insert(bin.end(), indices.begin(), indices.end());
  auto compressed = [](size_t offset, size_t length, int stride, int count, const char* mode) {
    return json{{"EXT_meshopt_compression",
                 {{"buffer", 0},
                  {"byteOffset", offset},
                  {"byteLength", length},
                  {"byteStride", stride},
                  {"count", count},
                  {"mode", mode}}}};
  };
  json g = {
      {"asset", {{"version", "2.0"}}},
      {"buffers",
       {{{"byteLength", bin.size()}},
        {{"byteLength", 60}, {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}}}},
      {"bufferViews",
       {{{"buffer", 1},
         {"byteLength", 48},
         {"byteStride", 12},
         {"extensions", compressed(0, vertices.size(), 12, 4, "ATTRIBUTES")}},
        {{"buffer", 1},
         {"byteOffset", 48},
         {"byteLength", 12},
         {"extensions", compressed(indicesAt, indices.size(), 2, 6, "TRIANGLES")}}}},
      {"accessors",
       {{{"bufferView", 0},
         {"componentType", 5126},
         {"count", 4},
         {"type", "VEC3"},
         {"min", {0, 0, 0}},
         {"max", {1, 1, 0}}},
        {{"bufferView", 1}, {"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}}}},
      {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"indices", 1}}}}}}},
      {"nodes", {{{"mesh", 0}}}},
      {"scenes", {{{"nodes", {0}}}}},
      {"extensionsUsed", {"EXT_meshopt_compression"}},
      {"extensionsRequired", {"EXT_meshopt_compression"}},
  };
  return {g, bin};
}

Scene load(const CompressedQuad& quad, LoadWarnings& warnings) {
  const std::vector<uint8_t> bytes = test::glbFile(quad.gltf, quad.bin);
  return loadGltfBytes("quad.glb", bytes.data(), bytes.size(), warnings);
}

std::string errorOf(const CompressedQuad& quad) {
  LoadWarnings warnings;
  try {
    load(quad, warnings);
  } catch (const LoadError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected a LoadError";
  return {};
}

TEST(GltfMeshopt, CompressedBufferViewsAreDecoded) {
  LoadWarnings warnings;
  const Scene s = load(compressedQuad(), warnings);
  EXPECT_TRUE(warnings.messages.empty()) << warnings.messages[0];
  ASSERT_EQ(s.meshes.size(), 1u);
  const Mesh& m = s.meshes[0];
  ASSERT_EQ(m.triangleCount(), 2u);
  ASSERT_EQ(m.indices.size(), kIndices.size());
  for (size_t i = 0; i < kIndices.size(); ++i) {
    const Vec3 p = m.positions[m.indices[i]];
    const float* expected = &kPositions[3 * kIndices[i]];
    EXPECT_EQ(p.x, expected[0]) << i;
    EXPECT_EQ(p.y, expected[1]) << i;
    EXPECT_EQ(p.z, expected[2]) << i;
  }
}

// The fallback buffer need not carry the extension's `fallback` marker.
TEST(GltfMeshopt, UnmarkedFallbackBufferWithoutDataIsDecodedInto) {
  CompressedQuad quad = compressedQuad();
  quad.gltf["buffers"][1].erase("extensions");
  LoadWarnings warnings;
  const Scene s = load(quad, warnings);
  ASSERT_EQ(s.meshes.size(), 1u);
  EXPECT_EQ(s.meshes[0].triangleCount(), 2u);
}

TEST(GltfMeshopt, DamagedOrForgedDataIsOneLineNamingTheBufferView) {
  CompressedQuad quad = compressedQuad();
  quad.gltf["bufferViews"][0]["extensions"]["EXT_meshopt_compression"]["count"] = 100000000;
  EXPECT_NE(errorOf(quad).find("quad.glb: bufferViews[0].extensions.EXT_meshopt_compression: 'count' claims more"),
            std::string::npos);

  quad = compressedQuad();
  std::fill(quad.bin.begin(), quad.bin.begin() + 8, uint8_t(0xff));  // the vertex stream's header
  EXPECT_NE(errorOf(quad).find("bufferViews[0].extensions.EXT_meshopt_compression: the compressed data cannot be "
                               "decoded"),
            std::string::npos);

  quad = compressedQuad();
  quad.gltf["bufferViews"][1]["extensions"]["EXT_meshopt_compression"]["byteLength"] = 1 << 20;
  EXPECT_NE(errorOf(quad).find("bufferViews[1].extensions.EXT_meshopt_compression: byteOffset 72 and byteLength "
                               "1048576 reach beyond the"),
            std::string::npos)
      << errorOf(quad);
}

// Offsets beyond any buffer, in the extension or in the bufferView the data decode into, are refused.
TEST(GltfMeshopt, OffsetsBeyondTheBuffersAreRefused) {
  const uint64_t huge = uint64_t(1) << 62;
  CompressedQuad quad = compressedQuad();
  quad.gltf["bufferViews"][0]["extensions"]["EXT_meshopt_compression"]["byteOffset"] = huge;
  EXPECT_EQ(errorOf(quad),
            "quad.glb: bufferViews[0].extensions.EXT_meshopt_compression.byteOffset: 4611686018427387904 is not a "
            "whole number from 0 to 2147483647");
  quad = compressedQuad();
  quad.gltf["bufferViews"][0]["byteOffset"] = huge;
  EXPECT_EQ(errorOf(quad),
            "quad.glb: bufferViews[0]: byteOffset 4611686018427387904 and byteLength 48 reach beyond the 60 bytes of "
            "buffers[1]");
  quad = compressedQuad();
  quad.gltf["bufferViews"][0]["extensions"]["EXT_meshopt_compression"]["byteOffset"] = -4;
  EXPECT_EQ(errorOf(quad),
            "quad.glb: bufferViews[0].extensions.EXT_meshopt_compression.byteOffset: -4 is not a whole number from 0 "
            "to 2147483647");
}

// bufferViews that decode the same stream share one decoding; streams that differ are added up, and refused
// before any is decoded when together they claim more than the compressed bytes can hold.
TEST(GltfMeshopt, RepeatedStreamsAreDecodedOnceAndDistinctOnesBounded) {
  CompressedQuad quad = compressedQuad();
  for (int i = 0; i < 1000; ++i) quad.gltf["bufferViews"].push_back(quad.gltf["bufferViews"][0]);
  LoadWarnings warnings;
  EXPECT_EQ(load(quad, warnings).triangleCount(), 2u);

  quad = compressedQuad();
  json view = quad.gltf["bufferViews"][0];
  for (int i = 0; i < 1000; ++i) {
    view["extensions"]["EXT_meshopt_compression"]["count"] = 1000 + i;
    view["byteLength"] = 12 * (1000 + i);
    quad.gltf["buffers"][1]["byteLength"] = 12 * (1000 + i);
    quad.gltf["bufferViews"].push_back(view);
  }
  const std::string error = errorOf(quad);
  EXPECT_NE(error.find("quad.glb: bufferViews["), std::string::npos) << error;
  EXPECT_NE(error.find("].extensions.EXT_meshopt_compression: the compressed bufferViews up to this one decode to "),
            std::string::npos)
      << error;
  EXPECT_NE(error.find("more than 256 times the"), std::string::npos) << error;
}

// A stream's decoded bytes are charged to the load's budget before it is decoded: a view that claims more than the
// load may use, though within what its compressed bytes could hold, is refused in one line with nothing allocated.
// A file that fits gives its charge back with the model.
TEST(GltfMeshopt, DecodedBytesBeyondTheLoadBudgetAreRefusedBeforeDecoding) {
  setProcessMemoryLimit(uint64_t(1) << 30);  // a budget of at most 512 MiB
  beginLoadBudget();
  const uint64_t left = loadMemoryLeft();
  LoadWarnings warnings;
  EXPECT_EQ(load(compressedQuad(), warnings).triangleCount(), 2u);
  EXPECT_EQ(loadMemoryLeft(), left);

  // 4 MiB of compressed bytes (no valid stream: nothing reads them) that claim 1 GiB decoded.
  CompressedQuad quad = compressedQuad();
  quad.bin.assign(size_t(4) << 20, 0);
  quad.gltf["buffers"][0]["byteLength"] = quad.bin.size();
  json& stream = quad.gltf["bufferViews"][0]["extensions"]["EXT_meshopt_compression"];
  stream["byteLength"] = quad.bin.size();
  stream["byteStride"] = 256;
  stream["count"] = 4 << 20;
  const std::string error = errorOf(quad);
  setProcessMemoryLimit(0);
  beginLoadBudget();
  EXPECT_NE(error.find("quad.glb: bufferViews[0] decoded from EXT_meshopt_compression needs about 1.0 GiB"),
            std::string::npos)
      << error;
  EXPECT_NE(error.find("--max-memory"), std::string::npos) << error;
}

}  // namespace
}  // namespace candela
