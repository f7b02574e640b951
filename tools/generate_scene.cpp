// Writes large test scenes shaped like a real one: a town of blocks with windowed facades, trees, lamp posts,
// rocks and a terrain, with many materials and textures. The same geometry goes to an OBJ (+MTL) and a glTF
// (.gltf + .bin), both with normals and texture coordinates; the PNG textures are shared.
//
//   candela-generate-scene --triangles 10000000 --out /tmp/town10m [--materials 300] [--textures 48]
//                          [--format obj|gltf|both]
#include <stb/stb_image_write.h>
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

namespace {

struct V3 {
  float x, y, z;
};
V3 operator+(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V3 operator*(V3 a, float s) { return {a.x * s, a.y * s, a.z * s}; }

// One object: an indexed triangle mesh with one material.
struct Part {
  std::vector<V3> p, n;
  std::vector<float> uv;  // 2 per vertex, v = 0 at the top of the image
  std::vector<uint32_t> idx;
  uint32_t material = 0;
  size_t triangles() const { return idx.size() / 3; }
};

// A (rows x cols) grid spanning origin + u*s + v*t, s, t in [0, 1], facing cross(u, v).
void grid(Part& m, V3 origin, V3 u, V3 v, int rows, int cols, float uvScale) {
  V3 normal{u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x};
  float len = std::sqrt(normal.x * normal.x + normal.y * normal.y + normal.z * normal.z);
  normal = normal * (1.0f / len);
  uint32_t base = uint32_t(m.p.size());
  for (int r = 0; r <= rows; ++r)
    for (int c = 0; c <= cols; ++c) {
      float s = float(c) / float(cols), t = float(r) / float(rows);
      m.p.push_back(origin + u * s + v * t);
      m.n.push_back(normal);
      m.uv.push_back(s * uvScale);
      m.uv.push_back(1.0f - t * uvScale);
    }
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      uint32_t a = base + uint32_t(r * (cols + 1) + c), b = a + 1, d = a + uint32_t(cols + 1), e = d + 1;
      m.idx.insert(m.idx.end(), {a, b, e, a, e, d});
    }
}

// A latitude-longitude sphere with its radius wobbled by `roughness` (rocks, tree crowns).
void blob(Part& m, V3 centre, V3 radius, int segments, float roughness, std::mt19937& rng) {
  std::uniform_real_distribution<float> phase(0.0f, 6.28f);
  float a = phase(rng), b = phase(rng);
  int rings = std::max(segments / 2, 2);
  uint32_t base = uint32_t(m.p.size());
  for (int r = 0; r <= rings; ++r)
    for (int s = 0; s <= segments; ++s) {
      float theta = 3.14159265f * float(r) / float(rings), phi = 6.2831853f * float(s) / float(segments);
      V3 d{std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)};
      float w = 1.0f + roughness * std::sin(3.0f * phi + a) * std::sin(4.0f * theta + b);
      m.p.push_back({centre.x + d.x * radius.x * w, centre.y + d.y * radius.y * w, centre.z + d.z * radius.z * w});
      m.n.push_back(d);
      m.uv.push_back(float(s) / float(segments) * 4.0f);
      m.uv.push_back(float(r) / float(rings) * 2.0f);
    }
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      uint32_t i0 = base + uint32_t(r * (segments + 1) + s), i1 = i0 + 1, i2 = i0 + uint32_t(segments + 1), i3 = i2 + 1;
      m.idx.insert(m.idx.end(), {i0, i1, i3, i0, i3, i2});
    }
}

// A box of `size` standing on `base` without a floor, each wall a grid of cells about `cell` metres wide
// (windows), all faces wound outwards.
void building(Part& m, V3 base, V3 size, float cell) {
  int cw = std::max(1, int(size.x / cell)), ch = std::max(1, int(size.y / cell)), cd = std::max(1, int(size.z / cell));
  V3 X{size.x, 0, 0}, Y{0, size.y, 0}, Z{0, 0, size.z};
  grid(m, base + Z, X, Y, ch, cw, float(cw));              // +z
  grid(m, base + X + Z, Z * -1.0f, Y, ch, cd, float(cd));  // +x
  grid(m, base, Z, Y, ch, cd, float(cd));                  // -x
  grid(m, base + X, X * -1.0f, Y, ch, cw, float(cw));      // -z
  grid(m, base + Y + Z, X, Z * -1.0f, cd, cw, 1.0f);       // roof
}

std::string number(float f) {
  char buffer[32];
  auto result = std::to_chars(buffer, buffer + sizeof buffer, f);
  return std::string(buffer, result.ptr);
}

void writeTexture(const std::filesystem::path& path, int seed) {
  const int size = 256;
  std::vector<uint8_t> rgb(size * size * 3);
  std::mt19937 rng{uint32_t(seed)};
  uint8_t base[3] = {uint8_t(rng() % 200 + 40), uint8_t(rng() % 200 + 40), uint8_t(rng() % 200 + 40)};
  int period = 8 << (seed % 4);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      bool line = (x % period) < 2 || (y % period) < 2;
      for (int c = 0; c < 3; ++c) rgb[size_t(y * size + x) * 3 + c] = line ? uint8_t(base[c] / 3) : base[c];
    }
  stbi_write_png(path.string().c_str(), size, size, 3, rgb.data(), size * 3);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Writes a large town-like test scene as OBJ and glTF"};
  size_t targetTriangles = 1'000'000;
  std::string out = "generated-scene", format = "both";
  int materials = 300, textures = 48;
  unsigned seed = 1;
  app.add_option("--triangles", targetTriangles, "About how many triangles")
      ->check(CLI::Range(size_t(1000), size_t(200'000'000)));
  app.add_option("--out", out, "Output folder")->required();
  app.add_option("--materials", materials, "Number of materials")->check(CLI::Range(1, 100000));
  app.add_option("--textures", textures, "Number of PNG textures")->check(CLI::Range(0, 10000));
  app.add_option("--format", format, "obj, gltf or both")->check(CLI::IsMember({"obj", "gltf", "both"}));
  app.add_option("--seed", seed, "Random seed");
  CLI11_PARSE(app, argc, argv);

  namespace fs = std::filesystem;
  fs::create_directories(fs::path(out) / "textures");
  for (int t = 0; t < textures; ++t) writeTexture(fs::path(out) / "textures" / ("tex" + std::to_string(t) + ".png"), t);

  // A square town: blocks of buildings along streets, trees and lamp posts between them, rocks on the terrain.
  // The detail (cells per facade, segments per tree) grows with the target so that the object count stays
  // near a few thousand per million triangles, like an architectural scene.
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u01(0.0f, 1.0f);
  const size_t objects = std::max<size_t>(50, targetTriangles / 2500);
  const float detail = std::sqrt(float(targetTriangles) / float(objects) / 2500.0f);
  const int side = int(std::ceil(std::sqrt(double(objects))));
  std::vector<Part> parts;
  size_t triangles = 0;
  Part terrain;
  int terrainCells = std::max(8, int(std::sqrt(double(targetTriangles) * 0.05 / 2.0)));
  grid(terrain, {0, 0, float(side) * 12.0f}, {float(side) * 12.0f, 0, 0}, {0, 0, -float(side) * 12.0f}, terrainCells,
       terrainCells, 40.0f);
  terrain.material = 0;
  triangles += terrain.triangles();
  parts.push_back(std::move(terrain));
  for (size_t i = 0; triangles < targetTriangles; ++i) {
    Part part;
    float x = float(i % size_t(side)) * 12.0f + 6.0f, z = float(i / size_t(side) % size_t(side)) * 12.0f + 6.0f;
    float y = float(i / size_t(side * side)) * 0.0f;
    switch (i % 4) {
      case 0:
      case 1: {
        V3 size{4.0f + 4.0f * u01(rng), 6.0f + 30.0f * u01(rng), 4.0f + 4.0f * u01(rng)};
        building(part, {x - size.x / 2, y, z - size.z / 2}, size, 1.5f / detail);
        break;
      }
      case 2: {
        int segments = std::max(8, int(24.0f * detail));
        blob(part, {x, y + 1.5f, z}, {0.2f, 1.5f, 0.2f}, std::max(6, segments / 3), 0.0f, rng);  // trunk
        blob(part, {x, y + 4.0f, z}, {2.0f, 2.5f, 2.0f}, segments, 0.15f, rng);                  // crown
        break;
      }
      default: {
        int segments = std::max(8, int(40.0f * detail));
        blob(part, {x, y + 0.5f, z}, {1.5f * u01(rng) + 0.5f, 0.8f, 1.2f}, segments, 0.3f, rng);
      }
    }
    part.material = uint32_t(1 + i % size_t(std::max(materials - 1, 1))) % uint32_t(materials);
    triangles += part.triangles();
    parts.push_back(std::move(part));
  }

  auto textureOf = [&](int m) { return textures > 0 && m % 3 != 2 ? m % textures : -1; };
  if (format != "gltf") {
    std::ofstream mtl(fs::path(out) / "scene.mtl");
    for (int m = 0; m < materials; ++m) {
      std::mt19937 mr(uint32_t(m) * 7919u);
      mtl << "newmtl m" << m << "\nKd " << number(0.2f + 0.6f * float(mr() % 100) / 100.0f) << " "
          << number(0.2f + 0.6f * float(mr() % 100) / 100.0f) << " " << number(0.2f + 0.6f * float(mr() % 100) / 100.0f)
          << "\n";
      if (m % 5 == 1) mtl << "Ks 0.3 0.3 0.3\nNs 60\n";
      if (textureOf(m) >= 0) mtl << "map_Kd textures/tex" << textureOf(m) << ".png\n";
    }
    std::ofstream obj(fs::path(out) / "scene.obj", std::ios::binary);
    std::string buffer;
    buffer.reserve(1 << 24);
    buffer += "mtllib scene.mtl\n";
    uint64_t vertexBase = 1;
    for (size_t k = 0; k < parts.size(); ++k) {
      const Part& p = parts[k];
      buffer += "o object" + std::to_string(k) + "\n";
      for (const V3& v : p.p) buffer += "v " + number(v.x) + " " + number(v.y) + " " + number(v.z) + "\n";
      for (size_t i = 0; i < p.p.size(); ++i)
        buffer += "vt " + number(p.uv[2 * i]) + " " + number(1.0f - p.uv[2 * i + 1]) + "\n";
      for (const V3& n : p.n) buffer += "vn " + number(n.x) + " " + number(n.y) + " " + number(n.z) + "\n";
      buffer += "usemtl m" + std::to_string(p.material) + "\n";
      for (size_t t = 0; t < p.triangles(); ++t) {
        buffer += "f";
        for (int c = 0; c < 3; ++c) {
          std::string i = std::to_string(vertexBase + p.idx[3 * t + size_t(c)]);
          buffer += " " + i + "/" + i + "/" + i;
        }
        buffer += "\n";
      }
      vertexBase += p.p.size();
      if (buffer.size() > (1 << 24) - (1 << 20)) {
        obj.write(buffer.data(), std::streamsize(buffer.size()));
        buffer.clear();
      }
    }
    obj.write(buffer.data(), std::streamsize(buffer.size()));
  }
  if (format != "obj") {
    using nlohmann::json;
    json gltf = {{"asset", {{"version", "2.0"}, {"generator", "candela-generate-scene"}}}};
    std::ofstream bin(fs::path(out) / "scene.bin", std::ios::binary);
    size_t offset = 0;
    auto addView = [&](const void* data, size_t bytes) {
      bin.write(static_cast<const char*>(data), std::streamsize(bytes));
      gltf["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes}});
      offset += bytes;
      return gltf["bufferViews"].size() - 1;
    };
    for (int t = 0; t < textures; ++t) {
      gltf["images"].push_back({{"uri", "textures/tex" + std::to_string(t) + ".png"}});
      gltf["textures"].push_back({{"source", t}});
    }
    for (int m = 0; m < materials; ++m) {
      std::mt19937 mr(uint32_t(m) * 7919u);
      json pbr = {{"baseColorFactor",
                   {0.2f + 0.6f * float(mr() % 100) / 100.0f, 0.2f + 0.6f * float(mr() % 100) / 100.0f,
                    0.2f + 0.6f * float(mr() % 100) / 100.0f, 1.0f}},
                  {"metallicFactor", m % 7 == 3 ? 1.0 : 0.0},
                  {"roughnessFactor", 0.3 + 0.6 * double(m % 10) / 10.0}};
      if (textureOf(m) >= 0) pbr["baseColorTexture"] = {{"index", textureOf(m)}};
      gltf["materials"].push_back({{"name", "m" + std::to_string(m)}, {"pbrMetallicRoughness", pbr}});
    }
    for (size_t k = 0; k < parts.size(); ++k) {
      const Part& p = parts[k];
      V3 lo{1e30f, 1e30f, 1e30f}, hi{-1e30f, -1e30f, -1e30f};
      for (const V3& v : p.p) {
        lo = {std::min(lo.x, v.x), std::min(lo.y, v.y), std::min(lo.z, v.z)};
        hi = {std::max(hi.x, v.x), std::max(hi.y, v.y), std::max(hi.z, v.z)};
      }
      size_t accessor = gltf["accessors"].size();
      gltf["accessors"].push_back({{"bufferView", addView(p.p.data(), p.p.size() * 12)},
                                   {"componentType", 5126},
                                   {"count", p.p.size()},
                                   {"type", "VEC3"},
                                   {"min", {lo.x, lo.y, lo.z}},
                                   {"max", {hi.x, hi.y, hi.z}}});
      gltf["accessors"].push_back({{"bufferView", addView(p.n.data(), p.n.size() * 12)},
                                   {"componentType", 5126},
                                   {"count", p.n.size()},
                                   {"type", "VEC3"}});
      gltf["accessors"].push_back({{"bufferView", addView(p.uv.data(), p.uv.size() * 4)},
                                   {"componentType", 5126},
                                   {"count", p.uv.size() / 2},
                                   {"type", "VEC2"}});
      gltf["accessors"].push_back({{"bufferView", addView(p.idx.data(), p.idx.size() * 4)},
                                   {"componentType", 5125},
                                   {"count", p.idx.size()},
                                   {"type", "SCALAR"}});
      json primitive = {{"attributes",
                         {{"POSITION", accessor}, {"NORMAL", accessor + 1}, {"TEXCOORD_0", accessor + 2}}},
                        {"indices", accessor + 3},
                        {"material", p.material}};
      gltf["meshes"].push_back({{"primitives", json::array({primitive})}});
      gltf["nodes"].push_back({{"mesh", k}});
      gltf["scenes"][0]["nodes"].push_back(k);
    }
    gltf["buffers"] = {{{"uri", "scene.bin"}, {"byteLength", offset}}};
    std::ofstream(fs::path(out) / "scene.gltf") << gltf.dump();
  }
  std::printf("%zu triangles in %zu objects, %d materials, %d textures -> %s\n", triangles, parts.size(), materials,
              textures, out.c_str());
  return 0;
}
