// repeated_gltf_inputs <folder>: writes glTF files that reference one piece of data many times (a Draco stream, a
// meshopt stream, an accessor), each beside the same data referenced once, for bounded_gltf_loads.py to render
// and measure. Made at test time so that no large file is committed.
#include <draco/compression/encode.h>
#include <draco/mesh/triangle_soup_mesh_builder.h>
#include <meshoptimizer.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "support/glb_file.h"

namespace {

using nlohmann::json;

// A square of side 1 in z = 0 made of a grid of side x side quads.
constexpr int kSide = 400;

struct Grid {
  std::vector<float> positions;   // xyz per vertex
  std::vector<uint32_t> indices;  // a triangle list
};

Grid grid() {
  Grid g;
  for (int j = 0; j <= kSide; ++j)
    for (int i = 0; i <= kSide; ++i) g.positions.insert(g.positions.end(), {float(i) / kSide, float(j) / kSide, 0});
  auto at = [](int i, int j) { return uint32_t(j * (kSide + 1) + i); };
  for (int j = 0; j < kSide; ++j)
    for (int i = 0; i < kSide; ++i)
      g.indices.insert(g.indices.end(),
                       {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j), at(i + 1, j + 1), at(i, j + 1)});
  return g;
}

template <class T>
void append(std::vector<uint8_t>& bin, const std::vector<T>& values) {
  const auto* p = reinterpret_cast<const uint8_t*>(values.data());
  bin.insert(bin.end(), p, p + values.size() * sizeof(T));
  bin.resize((bin.size() + 3) / 4 * 4, 0);
}

void write(const std::string& path, const std::vector<uint8_t>& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  if (!out) {
    std::fprintf(stderr, "cannot write %s\n", path.c_str());
    std::exit(1);
  }
}

json accessors(size_t vertices, size_t indices, bool withViews) {
  json position = {{"componentType", 5126}, {"count", vertices}, {"type", "VEC3"}},
       index = {{"componentType", 5125}, {"count", indices}, {"type", "SCALAR"}};
  position["min"] = {0, 0, 0};
  position["max"] = {1, 1, 0};
  if (withViews) {
    position["bufferView"] = 0;
    index["bufferView"] = 1;
  }
  return {position, index};
}

// `meshes` meshes of `primitives` primitives each, every one naming `primitive`, one node per mesh in a row.
json meshesAndNodes(json& g, const json& primitive, int meshes, int primitives) {
  g["meshes"] = json::array();
  g["nodes"] = json::array();
  json roots = json::array();
  const int perRow = 100;
  for (int m = 0; m < meshes; ++m) {
    g["meshes"].push_back({{"primitives", json::array()}});
    for (int p = 0; p < primitives; ++p) g["meshes"][size_t(m)]["primitives"].push_back(primitive);
    g["nodes"].push_back({{"mesh", m}, {"translation", {1.25 * (m % perRow), 1.25 * (m / perRow), 0}}});
    roots.push_back(m);
  }
  g["scenes"] = {{{"nodes", roots}}};
  return g;
}

// Plain accessors into the BIN chunk, named by `meshes` meshes of `primitives` primitives each.
std::vector<uint8_t> sharedAccessors(const Grid& grid, int meshes, int primitives) {
  std::vector<uint8_t> bin;
  append(bin, grid.positions);
  const size_t indicesAt = bin.size();
  append(bin, grid.indices);
  json g = {{"asset", {{"version", "2.0"}}},
            {"buffers", {{{"byteLength", bin.size()}}}},
            {"bufferViews",
             {{{"buffer", 0}, {"byteLength", indicesAt}},
              {{"buffer", 0}, {"byteOffset", indicesAt}, {"byteLength", bin.size() - indicesAt}}}},
            {"accessors", accessors(grid.positions.size() / 3, grid.indices.size(), true)}};
  meshesAndNodes(g, {{"attributes", {{"POSITION", 0}}}, {"indices", 1}}, meshes, primitives);
  return candela::test::glbFile(g, bin);
}

std::vector<uint8_t> dracoStream(const Grid& grid, int& positionId) {
  draco::TriangleSoupMeshBuilder builder;
  const int faces = int(grid.indices.size() / 3);
  builder.Start(faces);
  const int position = builder.AddAttribute(draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT32);
  for (int f = 0; f < faces; ++f) {
    const uint32_t* c = &grid.indices[size_t(3 * f)];
    builder.SetAttributeValuesForFace(position, draco::FaceIndex(f), &grid.positions[3 * c[0]],
                                      &grid.positions[3 * c[1]], &grid.positions[3 * c[2]]);
  }
  std::unique_ptr<draco::Mesh> mesh = builder.Finalize();
  positionId = int(mesh->attribute(position)->unique_id());
  draco::Encoder encoder;
  encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, 14);
  draco::EncoderBuffer out;
  if (!encoder.EncodeMeshToBuffer(*mesh, &out).ok()) {
    std::fprintf(stderr, "Draco cannot encode the grid\n");
    std::exit(1);
  }
  return std::vector<uint8_t>(out.data(), out.data() + out.size());
}

// One Draco stream named by `primitives` primitives of one mesh.
std::vector<uint8_t> sharedDracoView(const std::vector<uint8_t>& draco, int positionId, const Grid& grid,
                                     int primitives) {
  json g = {{"asset", {{"version", "2.0"}}},
            {"extensionsUsed", {"KHR_draco_mesh_compression"}},
            {"extensionsRequired", {"KHR_draco_mesh_compression"}},
            {"buffers", {{{"byteLength", (draco.size() + 3) / 4 * 4}}}},
            {"bufferViews", {{{"buffer", 0}, {"byteLength", draco.size()}}}},
            {"accessors", accessors(grid.positions.size() / 3, grid.indices.size(), false)}};
  json primitive = {
      {"attributes", {{"POSITION", 0}}},
      {"indices", 1},
      {"extensions",
       {{"KHR_draco_mesh_compression", {{"bufferView", 0}, {"attributes", {{"POSITION", positionId}}}}}}}};
  meshesAndNodes(g, primitive, 1, primitives);
  return candela::test::glbFile(g, draco);
}

// The grid's positions and indices compressed with meshopt, and `extraViews` more bufferViews that decode the
// same compressed positions again; with `distinctCounts` each of those claims one vertex fewer than the last, so
// that no two decode the same.
std::vector<uint8_t> repeatedMeshoptViews(const Grid& grid, int extraViews, bool distinctCounts) {
  const size_t vertices = grid.positions.size() / 3;
  std::vector<uint8_t> positions(meshopt_encodeVertexBufferBound(vertices, 12));
  positions.resize(meshopt_encodeVertexBuffer(positions.data(), positions.size(), grid.positions.data(), vertices, 12));
  std::vector<uint8_t> indices(meshopt_encodeIndexBufferBound(grid.indices.size(), vertices));
  indices.resize(meshopt_encodeIndexBuffer(indices.data(), indices.size(), grid.indices.data(), grid.indices.size()));
  std::vector<uint8_t> bin;
  append(bin, positions);
  const size_t indicesAt = bin.size();
  append(bin, indices);
  auto compressed = [](size_t offset, size_t length, size_t stride, size_t count, const char* mode) {
    return json{{"EXT_meshopt_compression",
                 {{"buffer", 0},
                  {"byteOffset", offset},
                  {"byteLength", length},
                  {"byteStride", stride},
                  {"count", count},
                  {"mode", mode}}}};
  };
  const size_t positionBytes = vertices * 12, indexBytes = grid.indices.size() * 4;
  json views = {{{"buffer", 1},
                 {"byteLength", positionBytes},
                 {"byteStride", 12},
                 {"extensions", compressed(0, positions.size(), 12, vertices, "ATTRIBUTES")}},
                {{"buffer", 1},
                 {"byteOffset", positionBytes},
                 {"byteLength", indexBytes},
                 {"extensions", compressed(indicesAt, indices.size(), 4, grid.indices.size(), "TRIANGLES")}}};
  for (int v = 0; v < extraViews; ++v) {
    const size_t count = distinctCounts ? vertices - size_t(v) - 1 : vertices;
    views.push_back({{"buffer", 1},
                     {"byteLength", count * 12},
                     {"byteStride", 12},
                     {"extensions", compressed(0, positions.size(), 12, count, "ATTRIBUTES")}});
  }
  json g = {
      {"asset", {{"version", "2.0"}}},
      {"extensionsUsed", {"EXT_meshopt_compression"}},
      {"extensionsRequired", {"EXT_meshopt_compression"}},
      {"buffers",
       {{{"byteLength", bin.size()}},
        {{"byteLength", positionBytes + indexBytes},
         {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}}}},
      {"bufferViews", views},
      {"accessors", accessors(vertices, grid.indices.size(), true)},
  };
  meshesAndNodes(g, {{"attributes", {{"POSITION", 0}}}, {"indices", 1}}, 1, 1);
  return candela::test::glbFile(g, bin);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: repeated_gltf_inputs <folder>\n");
    return 2;
  }
  const std::string folder = argv[1];
  const Grid g = grid();
  write(folder + "/accessor-1-mesh.glb", sharedAccessors(g, 1, 1));
  write(folder + "/accessor-5000-meshes.glb", sharedAccessors(g, 5000, 1));
  write(folder + "/accessor-5000-primitives.glb", sharedAccessors(g, 1, 5000));
  int positionId = 0;
  const std::vector<uint8_t> draco = dracoStream(g, positionId);
  write(folder + "/draco-1-primitive.glb", sharedDracoView(draco, positionId, g, 1));
  write(folder + "/draco-500-primitives.glb", sharedDracoView(draco, positionId, g, 500));
  write(folder + "/meshopt-1-view.glb", repeatedMeshoptViews(g, 0, false));
  // The decoded views add up to about 1,000 and 4,000 times the file.
  const std::vector<uint8_t> one = repeatedMeshoptViews(g, 0, false);
  const size_t perView = g.positions.size() * 4;
  write(folder + "/meshopt-x1000-same.glb", repeatedMeshoptViews(g, int(1000 * one.size() / perView), false));
  write(folder + "/meshopt-x4000-distinct.glb", repeatedMeshoptViews(g, int(4000 * one.size() / perView), true));
  return 0;
}
