#include "media/nanovdb_files.h"

#include <cstring>
#include <map>

#include <zlib.h>

namespace candela::test {

namespace {

constexpr uint64_t kMagicGrid = 0x314244566f6e614eull;  // "NanoVDB1"
constexpr uint64_t kMagicFile = 0x324244566f6e614eull;  // "NanoVDB2"
constexpr uint32_t kVersion = (32u << 21) | (9u << 10) | 2u;
constexpr size_t kGridData = 672, kTreeData = 64, kRoot = 64, kRootTile = 32;
constexpr size_t kUpper = 270400, kLower = 33856, kLeaf = 2144;

template <typename T>
void put(std::vector<uint8_t>& b, size_t at, T v) {
  std::memcpy(b.data() + at, &v, sizeof(T));
}

struct Coord {
  int32_t x, y, z;
  bool operator<(const Coord& o) const { return x != o.x ? x < o.x : y != o.y ? y < o.y : z < o.z; }
};

Coord floorTo(int32_t x, int32_t y, int32_t z, int32_t side) {
  auto f = [&](int32_t v) { return int32_t(int64_t(v) & ~int64_t(side - 1)); };
  return {f(x), f(y), f(z)};
}

}  // namespace

std::vector<uint8_t> nanoVdbGridBytes(const TestNanoVdbGrid& g) {
  // The value of each voxel, the background outside the box.
  auto value = [&](int32_t x, int32_t y, int32_t z) {
    const int64_t i = int64_t(x) - g.origin[0], j = int64_t(y) - g.origin[1], k = int64_t(z) - g.origin[2];
    if (i < 0 || j < 0 || k < 0 || i >= g.size[0] || j >= g.size[1] || k >= g.size[2]) return g.background;
    return g.values[size_t((k * g.size[1] + j) * g.size[0] + i)];
  };
  // The leaves the box touches, and their lower, upper and root-tile parents.
  std::map<Coord, std::vector<float>> leaves;
  std::map<Coord, float> lowerTiles;  // pruned leaves: one value
  for (uint32_t k = 0; k < g.size[2]; ++k)
    for (uint32_t j = 0; j < g.size[1]; ++j)
      for (uint32_t i = 0; i < g.size[0]; ++i) {
        const Coord leaf = floorTo(g.origin[0] + int32_t(i), g.origin[1] + int32_t(j), g.origin[2] + int32_t(k), 8);
        if (leaves.count(leaf)) continue;
        std::vector<float> v(512);
        for (int n = 0; n < 512; ++n)
          v[size_t(n)] = value(leaf.x + (n >> 6), leaf.y + ((n >> 3) & 7), leaf.z + (n & 7));
        leaves[leaf] = v;
      }
  for (auto it = leaves.begin(); it != leaves.end();) {
    bool uniform = true;
    for (float v : it->second) uniform = uniform && v == it->second[0];
    if (!uniform) {
      ++it;
      continue;
    }
    lowerTiles[it->first] = it->second[0];
    it = leaves.erase(it);
  }
  std::map<Coord, size_t> leafIndex, lowerIndex, upperIndex;
  for (const auto& [c, v] : leaves) leafIndex.emplace(c, leafIndex.size());
  auto noteParents = [&](const Coord& c) {
    lowerIndex.emplace(floorTo(c.x, c.y, c.z, 128), 0);
    upperIndex.emplace(floorTo(c.x, c.y, c.z, 4096), 0);
  };
  for (const auto& [c, v] : leaves) noteParents(c);
  for (const auto& [c, v] : lowerTiles) noteParents(c);
  size_t n = 0;
  for (auto& [c, i] : lowerIndex) i = n++;
  n = 0;
  for (auto& [c, i] : upperIndex) i = n++;

  const size_t rootAt = kGridData + kTreeData;
  const size_t upperAt = rootAt + kRoot + kRootTile * upperIndex.size();
  const size_t lowerAt = upperAt + kUpper * upperIndex.size();
  const size_t leafAt = lowerAt + kLower * lowerIndex.size();
  const size_t total = leafAt + kLeaf * leaves.size();
  std::vector<uint8_t> b(total, 0);

  put(b, 0, kMagicGrid);
  put(b, 16, kVersion);
  put(b, 28, uint32_t(1));  // grid count
  put(b, 32, uint64_t(total));
  std::memcpy(b.data() + 40, g.name.data(), std::min<size_t>(g.name.size(), 255));
  for (int a = 0; a < 3; ++a) {
    put(b, 296 + 4 * size_t(4 * a), float(g.voxelSize[size_t(a)]));             // matF diagonal
    put(b, 296 + 36 + 4 * size_t(4 * a), float(1.0 / g.voxelSize[size_t(a)]));  // invMatF
    put(b, 296 + 72 + 4 * size_t(a), float(g.translation[size_t(a)]));          // vecF
    put(b, 296 + 88 + 8 * size_t(4 * a), g.voxelSize[size_t(a)]);               // matD
    put(b, 296 + 160 + 8 * size_t(4 * a), 1.0 / g.voxelSize[size_t(a)]);        // invMatD
    put(b, 296 + 232 + 8 * size_t(a), g.translation[size_t(a)]);                // vecD
    put(b, 608 + 8 * size_t(a), g.voxelSize[size_t(a)]);
  }
  put(b, 296 + 84, 1.0f);
  put(b, 296 + 256, 1.0);
  put(b, 632, g.gridClass);
  put(b, 636, g.valueType);

  const size_t tree = kGridData;
  put(b, tree + 0, uint64_t(leaves.empty() ? 0 : leafAt - tree));
  put(b, tree + 8, uint64_t(lowerAt - tree));
  put(b, tree + 16, uint64_t(upperAt - tree));
  put(b, tree + 24, uint64_t(rootAt - tree));
  put(b, tree + 32, uint32_t(leaves.size()));
  put(b, tree + 36, uint32_t(lowerIndex.size()));
  put(b, tree + 40, uint32_t(upperIndex.size()));
  put(b, tree + 56, uint64_t(g.size[0]) * g.size[1] * g.size[2]);

  for (int a = 0; a < 3; ++a) {
    put(b, rootAt + 4 * size_t(a), g.origin[size_t(a)]);
    put(b, rootAt + 12 + 4 * size_t(a), g.origin[size_t(a)] + int32_t(g.size[size_t(a)]) - 1);
  }
  put(b, rootAt + 24, uint32_t(upperIndex.size()));
  put(b, rootAt + 28, g.background);
  for (const auto& [c, i] : upperIndex) {
    const size_t tile = rootAt + kRoot + kRootTile * i;
    const uint64_t key =
        uint64_t(uint32_t(c.z) >> 12) | (uint64_t(uint32_t(c.y) >> 12) << 21) | (uint64_t(uint32_t(c.x) >> 12) << 42);
    put(b, tile, key);
    put(b, tile + 8, int64_t(upperAt + kUpper * i) - int64_t(rootAt));
    put(b, tile + 16, uint32_t(1));
  }
  // Every table entry that is no child holds the background, as NanoVDB's inactive tiles do.
  for (const auto& [c, i] : upperIndex) {
    const size_t at = upperAt + kUpper * i;
    for (size_t e = 0; e < 32768; ++e) put(b, at + 8256 + 8 * e, g.background);
  }
  for (const auto& [c, i] : lowerIndex) {
    const size_t at = lowerAt + kLower * i;
    for (size_t e = 0; e < 4096; ++e) put(b, at + 1088 + 8 * e, g.background);
    const Coord up = floorTo(c.x, c.y, c.z, 4096);
    const size_t parent = upperAt + kUpper * upperIndex.at(up);
    const uint32_t e = uint32_t((((c.x - up.x) >> 7) << 10) | (((c.y - up.y) >> 7) << 5) | ((c.z - up.z) >> 7));
    b[parent + 4128 + e / 8] |= uint8_t(1u << (e % 8));
    put(b, parent + 8256 + 8 * size_t(e), int64_t(at) - int64_t(parent));
  }
  auto lowerEntry = [&](const Coord& c, size_t& lower) {
    const Coord lo = floorTo(c.x, c.y, c.z, 128);
    lower = lowerAt + kLower * lowerIndex.at(lo);
    return uint32_t((((c.x - lo.x) >> 3) << 8) | (((c.y - lo.y) >> 3) << 4) | ((c.z - lo.z) >> 3));
  };
  for (const auto& [c, v] : lowerTiles) {
    size_t lower;
    const uint32_t e = lowerEntry(c, lower);
    put(b, lower + 1088 + 8 * size_t(e), v);
    b[lower + 32 + e / 8] |= uint8_t(1u << (e % 8));  // active
  }
  for (const auto& [c, i] : leafIndex) {
    const size_t at = leafAt + kLeaf * i;
    size_t lower;
    const uint32_t e = lowerEntry(c, lower);
    b[lower + 544 + e / 8] |= uint8_t(1u << (e % 8));
    put(b, lower + 1088 + 8 * size_t(e), int64_t(at) - int64_t(lower));
    put(b, at + 0, c.x);
    put(b, at + 4, c.y);
    put(b, at + 8, c.z);
    std::memcpy(b.data() + at + 96, leaves.at(c).data(), 512 * sizeof(float));
  }
  return b;
}

std::string nanoVdbFile(const std::vector<TestNanoVdbGrid>& grids, bool zip) {
  std::vector<uint8_t> out(16, 0);
  put(out, 0, kMagicFile);
  put(out, 8, kVersion);
  put(out, 12, uint16_t(grids.size()));
  put(out, 14, uint16_t(zip ? 1 : 0));
  std::vector<std::vector<uint8_t>> stored;
  for (const TestNanoVdbGrid& g : grids) {
    const std::vector<uint8_t> bytes = nanoVdbGridBytes(g);
    std::vector<uint8_t> s = bytes;
    if (zip) {
      uLongf size = compressBound(uLong(bytes.size()));
      std::vector<uint8_t> z(size);
      compress(z.data(), &size, bytes.data(), uLong(bytes.size()));
      s.assign(8, 0);
      put(s, 0, uint64_t(size));
      s.insert(s.end(), z.begin(), z.begin() + long(size));
    }
    std::vector<uint8_t> meta(176, 0);
    put(meta, 0, uint64_t(bytes.size()));
    put(meta, 8, uint64_t(s.size()));
    put(meta, 32, g.valueType);
    put(meta, 36, g.gridClass);
    put(meta, 136, uint32_t(g.name.size() + 1));
    put(meta, 168, uint16_t(zip ? 1 : 0));
    put(meta, 172, kVersion);
    out.insert(out.end(), meta.begin(), meta.end());
    out.insert(out.end(), g.name.begin(), g.name.end());
    out.push_back(0);
    stored.push_back(std::move(s));
  }
  for (const std::vector<uint8_t>& s : stored) out.insert(out.end(), s.begin(), s.end());
  return std::string(out.begin(), out.end());
}

}  // namespace candela::test
