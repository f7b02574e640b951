#include "scene/loaders/nanovdb/nanovdb_dense_grid.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "io/load_budget.h"
#include "io/load_diagnostics.h"
#include "scene/loaders/nanovdb/nanovdb_file.h"

namespace candela {

namespace {

// NanoVDB 32's layout of a grid of floats (the byte offsets of PNanoVDB.h): GridData, TreeData, then the root,
// the upper nodes, the lower nodes and the leaves, each level one array.
constexpr uint64_t kGridDataBytes = 672;
constexpr uint64_t kTreeDataBytes = 64;
constexpr uint64_t kVersionAt = 16, kGridSizeAt = 32, kMapMatrixAt = 296 + 88, kMapTranslationAt = 296 + 232;
constexpr uint64_t kGridClassAt = 632, kGridTypeAt = 636;
constexpr uint64_t kRootBytes = 64, kRootBackgroundAt = 28, kRootTileBytes = 32, kRootTileValueAt = 20;
constexpr uint64_t kUpperBytes = 270400, kUpperChildMaskAt = 4128, kUpperTableAt = 8256;
constexpr uint64_t kLowerBytes = 33856, kLowerChildMaskAt = 544, kLowerTableAt = 1088;
constexpr uint64_t kLeafBytes = 2144, kLeafValuesAt = 96;
// Voxels a side of a root tile, an upper node's tile (and its lower nodes), a lower node's tile (a leaf).
constexpr int64_t kRootTileVoxels = 4096, kUpperTileVoxels = 128, kLowerTileVoxels = 8;
constexpr int64_t kMaxVoxelsPerSide = int64_t(1) << 20;
// The farthest index coordinate read: floats hold every integer up to it, so the box is placed exactly.
constexpr int64_t kMaxIndex = int64_t(1) << 24;

std::string gridClassName(uint32_t c) {
  static const char* const names[] = {"unknown",    "level set", "fog volume",   "staggered",  "point index",
                                      "point data", "topology",  "voxel volume", "index grid", "tensor grid"};
  return c < sizeof(names) / sizeof(names[0]) ? names[c] : "class " + std::to_string(c);
}

// One level of the tree: where its array begins in the grid's bytes, its nodes, and which were reached.
struct NodeLevel {
  uint64_t base = 0;
  uint64_t count = 0;
  uint64_t nodeBytes = 0;
  std::vector<uint8_t> reached;
};

// How the index box's voxels along one axis fall into the dense grid's cells: voxel u (0 to voxels - 1) lies in
// cell first[u] with weight inFirst[u], the rest in the next cell.
struct AxisCells {
  uint64_t voxels = 1, cells = 1;
  std::vector<uint32_t> first;
  std::vector<double> inFirst;

  AxisCells(uint64_t n, uint64_t m) : voxels(n), cells(m), first(n), inFirst(n) {
    for (uint64_t u = 0; u < n; ++u) {
      first[u] = uint32_t(u * m / n);
      inFirst[u] = std::min(1.0, cellEnd(first[u]) - double(u));
    }
  }
  // Where cell c ends, in voxels from the box's start.
  double cellEnd(uint64_t c) const { return double(c + 1) * double(voxels) / double(cells); }
  double cellStart(uint64_t c) const { return double(c) * double(voxels) / double(cells); }

  // The cells that the voxels [a, b) overlap (0 <= a < b <= voxels), with the overlaps' lengths.
  template <typename F>
  void forEachCell(uint64_t a, uint64_t b, F&& f) const {
    for (uint64_t c = a * cells / voxels; c < cells && cellStart(c) < double(b); ++c) {
      const double overlap = std::min(double(b), cellEnd(c)) - std::max(double(a), cellStart(c));
      if (overlap > 0.0) f(uint32_t(c), overlap);
    }
  }
};

class DenseGridWalk {
 public:
  DenseGridWalk(const std::vector<uint8_t>& bytes, const std::string& file, const std::string& gridName,
                NanoVdbValues accepted)
      : bytes_(bytes), file_(file), grid_(gridName), accepted_(accepted) {}

  // The samples over the grid's own index box (`like` null), or over the cells of `like`, another grid's.
  NanoVdbDenseGrid run(const NanoVdbDenseGrid* like, uint32_t maxResolution, std::vector<float>& values) {
    NanoVdbDenseGrid dense;
    readHeader(dense);
    const uint64_t rootAt = readTree();
    const uint32_t likeCells[3] = {like ? like->nx : 0, like ? like->ny : 0, like ? like->nz : 0};
    for (int a = 0; a < 3; ++a) {
      if (like) {
        dense.indexMin[a] = like->indexMin[a];
        dense.indexMax[a] = like->indexMax[a];
      } else {
        dense.indexMin[a] = read<int32_t>(rootAt + 4 * uint64_t(a));
        dense.indexMax[a] = read<int32_t>(rootAt + 12 + 4 * uint64_t(a));
      }
      lo_[a] = dense.indexMin[a];
      if (lo_[a] > int64_t(dense.indexMax[a])) fail("has no active voxels");
      if (std::max(-lo_[a], int64_t(dense.indexMax[a])) > kMaxIndex) fail("has voxels beyond 2^24 from its origin");
      const int64_t n = int64_t(dense.indexMax[a]) - lo_[a] + 1;
      if (n > kMaxVoxelsPerSide) fail("has a bounding box of " + std::to_string(n) + " voxels a side, more than 2^20");
      hi_[a] = int64_t(dense.indexMax[a]) + 1;
      const uint64_t m = std::min<uint64_t>(uint64_t(n), like ? std::max<uint32_t>(likeCells[a], 1) : maxResolution);
      axes_.emplace_back(uint64_t(n), m);
      dense.downsampled = dense.downsampled || m < uint64_t(n);
    }
    dense.nx = uint32_t(axes_[0].cells);
    dense.ny = uint32_t(axes_[1].cells);
    dense.nz = uint32_t(axes_[2].cells);
    const uint64_t count = uint64_t(dense.nx) * dense.ny * dense.nz;
    chargeLoadMemory(count * sizeof(float), file_, "grid '" + grid_ + "' as a dense grid");
    dense.offset = values.size();
    values.resize(values.size() + count, 0.0f);
    out_ = values.data() + dense.offset;
    walkRoot(rootAt);
    // The sums over each cell, divided by its volume (1 voxel without downsampling: the values stay as they are).
    const double perVoxel =
        double(count) / (double(axes_[0].voxels) * double(axes_[1].voxels) * double(axes_[2].voxels));
    if (dense.downsampled)
      for (uint64_t i = 0; i < count; ++i) out_[i] = float(double(out_[i]) * perVoxel);
    return dense;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { failLoad(file_, "grid '" + grid_ + "' " + what); }

  template <typename T>
  T read(uint64_t at) const {
    T v;
    std::memcpy(&v, bytes_.data() + at, sizeof(T));
    return v;
  }

  // A value the dense grid takes in: finite, and not negative for a density.
  float value(uint64_t at) const {
    const float v = read<float>(at);
    if (accepted_ == NanoVdbValues::Finite) {
      if (!std::isfinite(v)) fail("has a non-finite value (" + std::to_string(v) + ")");
    } else if (!std::isfinite(v) || v < 0.0f) {
      fail("has a negative or non-finite value (" + std::to_string(v) + ")");
    }
    return v;
  }

  void readHeader(NanoVdbDenseGrid& dense) const {
    if (bytes_.size() < kGridDataBytes + kTreeDataBytes) fail("is too short to be a NanoVDB grid");
    const uint64_t magic = read<uint64_t>(0);
    if (magic != kNanoVdbMagicOld && magic != kNanoVdbMagicGrid) fail("does not begin as a NanoVDB grid");
    if (read<uint32_t>(kVersionAt) >> 21 != kNanoVdbMajorVersion) fail("is not a NanoVDB 32 grid");
    if (read<uint64_t>(kGridSizeAt) > bytes_.size()) fail("states more bytes than it has");
    const uint32_t type = read<uint32_t>(kGridTypeAt), gridClass = read<uint32_t>(kGridClassAt);
    if (type != kNanoVdbFloat) fail("holds " + nanoVdbTypeName(type) + " values; only float grids are read");
    // As pbrt-v4: the grids of a medium are fog volumes (or grids of no stated class).
    if (gridClass != kNanoVdbClassFogVolume && gridClass != kNanoVdbClassUnknown)
      fail("is a " + gridClassName(gridClass) + ", not a fog volume");
    for (int row = 0; row < 3; ++row) {
      for (int col = 0; col < 3; ++col)
        dense.worldFromIndex[4 * row + col] = read<double>(kMapMatrixAt + 8 * uint64_t(3 * row + col));
      dense.worldFromIndex[4 * row + 3] = read<double>(kMapTranslationAt + 8 * uint64_t(row));
    }
    for (double v : dense.worldFromIndex)
      if (!std::isfinite(v)) fail("has a non-finite index-to-world map");
  }

  // Checks where the levels' arrays lie; returns where the root is.
  uint64_t readTree() {
    const uint64_t tree = kGridDataBytes, size = bytes_.size();
    auto level = [&](NodeLevel& l, uint64_t offsetAt, uint64_t countAt, uint64_t nodeBytes, const char* name) {
      l.count = read<uint32_t>(tree + countAt);
      l.nodeBytes = nodeBytes;
      if (l.count == 0) return;
      const uint64_t offset = read<uint64_t>(tree + offsetAt);
      if (offset > size - tree || l.count * nodeBytes > size - tree - offset)
        fail(std::string("states ") + std::to_string(l.count) + " " + name + " beyond its bytes");
      l.base = tree + offset;
      l.reached.assign(l.count, 0);
    };
    level(leaves_, 0, 32, kLeafBytes, "leaves");
    level(lower_, 8, 36, kLowerBytes, "lower nodes");
    level(upper_, 16, 40, kUpperBytes, "upper nodes");
    const uint64_t rootOffset = read<uint64_t>(tree + 24);
    if (rootOffset > size - tree || size - tree - rootOffset < kRootBytes) fail("has its root beyond its bytes");
    const uint64_t rootAt = tree + rootOffset;
    const uint64_t tiles = read<uint32_t>(rootAt + 24);
    if (tiles * kRootTileBytes > size - rootAt - kRootBytes)
      fail("states " + std::to_string(tiles) + " root tiles beyond its bytes");
    return rootAt;
  }

  // The node of `level` that the byte offset `offset` from the node at `from` names, marked reached.
  uint64_t child(uint64_t from, int64_t offset, NodeLevel& level, const char* name) {
    const uint64_t size = bytes_.size();
    const bool inside = offset >= 0 ? uint64_t(offset) < size - from : uint64_t(-(offset + 1)) < from;
    const uint64_t at = from + uint64_t(offset);
    if (!inside || at < level.base || (at - level.base) % level.nodeBytes != 0 ||
        (at - level.base) / level.nodeBytes >= level.count)
      fail(std::string("has a child offset that names no ") + name);
    uint8_t& reached = level.reached[(at - level.base) / level.nodeBytes];
    if (reached) fail(std::string("reaches one of its ") + name + " twice");
    reached = 1;
    return at;
  }

  // Adds `value` over the cube of `side` voxels from `origin`, as far as it lies in the index box.
  void addCube(const int64_t origin[3], int64_t side, float value) {
    if (value == 0.0f) return;
    uint64_t a[3], b[3];
    for (int k = 0; k < 3; ++k) {
      const int64_t from = std::max(origin[k], lo_[k]), to = std::min(origin[k] + side, hi_[k]);
      if (from >= to) return;
      a[k] = uint64_t(from - lo_[k]);
      b[k] = uint64_t(to - lo_[k]);
    }
    const uint64_t nx = axes_[0].cells, ny = axes_[1].cells;
    axes_[2].forEachCell(a[2], b[2], [&](uint32_t z, double wz) {
      axes_[1].forEachCell(a[1], b[1], [&](uint32_t y, double wy) {
        axes_[0].forEachCell(a[0], b[0], [&](uint32_t x, double wx) {
          out_[(uint64_t(z) * ny + y) * nx + x] += float(double(value) * wx * wy * wz);
        });
      });
    });
  }

  // Adds the value of one voxel of the index box (index coordinates): to one cell without downsampling, else to
  // the one or two cells per axis that it overlaps.
  void addVoxel(int64_t x, int64_t y, int64_t z, float value) {
    if (value == 0.0f) return;
    const uint64_t u[3] = {uint64_t(x - lo_[0]), uint64_t(y - lo_[1]), uint64_t(z - lo_[2])};
    uint64_t cell[3][2];
    double weight[3][2];
    int cells[3];
    for (int k = 0; k < 3; ++k) {
      cell[k][0] = axes_[k].first[u[k]];
      weight[k][0] = axes_[k].inFirst[u[k]];
      cell[k][1] = cell[k][0] + 1;
      weight[k][1] = 1.0 - weight[k][0];
      cells[k] = weight[k][1] > 0.0 ? 2 : 1;
    }
    const uint64_t nx = axes_[0].cells, ny = axes_[1].cells;
    for (int c = 0; c < cells[2]; ++c)
      for (int b = 0; b < cells[1]; ++b)
        for (int a = 0; a < cells[0]; ++a)
          out_[(cell[2][c] * ny + cell[1][b]) * nx + cell[0][a]] +=
              float(double(value) * weight[0][a] * weight[1][b] * weight[2][c]);
  }

  bool touchesBox(const int64_t origin[3], int64_t side) const {
    for (int k = 0; k < 3; ++k)
      if (origin[k] >= hi_[k] || origin[k] + side <= lo_[k]) return false;
    return true;
  }

  void walkRoot(uint64_t rootAt) {
    const uint32_t tiles = read<uint32_t>(rootAt + 24);
    // Where no root tile is, the grid is its background value: added over the whole box, taken back under the
    // tiles, which say what is there.
    const float background = value(rootAt + kRootBackgroundAt);
    const int64_t whole[3] = {lo_[0], lo_[1], lo_[2]};
    addCube(whole, kMaxVoxelsPerSide, background);
    std::vector<uint64_t> keys(tiles);
    for (uint32_t t = 0; t < tiles; ++t) {
      const uint64_t tileAt = rootAt + kRootBytes + uint64_t(t) * kRootTileBytes;
      const uint64_t key = read<uint64_t>(tileAt);
      keys[t] = key;
      int64_t origin[3];
      for (int k = 0; k < 3; ++k) {
        const uint64_t field = (key >> (42 - 21 * k)) & 0x1fffff;
        if (field >= (uint64_t(1) << 20)) fail("has a root tile of an impossible key");
        origin[k] = int64_t(int32_t(uint32_t(field << 12)));
      }
      if (!touchesBox(origin, kRootTileVoxels)) continue;
      addCube(origin, kRootTileVoxels, -background);
      const int64_t offset = read<int64_t>(tileAt + 8);
      if (offset == 0)
        addCube(origin, kRootTileVoxels, value(tileAt + kRootTileValueAt));
      else
        walkUpper(child(rootAt, offset, upper_, "upper node"), origin);
    }
    std::sort(keys.begin(), keys.end());
    if (std::adjacent_find(keys.begin(), keys.end()) != keys.end()) fail("has two root tiles of one key");
  }

  void walkUpper(uint64_t at, const int64_t origin[3]) {
    for (uint32_t n = 0; n < 32768; ++n) {
      const int64_t o[3] = {origin[0] + int64_t(n >> 10) * kUpperTileVoxels,
                            origin[1] + int64_t((n >> 5) & 31) * kUpperTileVoxels,
                            origin[2] + int64_t(n & 31) * kUpperTileVoxels};
      const uint64_t entry = at + kUpperTableAt + 8 * uint64_t(n);
      const bool isChild = (read<uint32_t>(at + kUpperChildMaskAt + 4 * uint64_t(n >> 5)) >> (n & 31)) & 1;
      if (!isChild) {
        if (touchesBox(o, kUpperTileVoxels)) addCube(o, kUpperTileVoxels, value(entry));
        continue;
      }
      const uint64_t lowerAt = child(at, read<int64_t>(entry), lower_, "lower node");
      if (touchesBox(o, kUpperTileVoxels)) walkLower(lowerAt, o);
    }
  }

  void walkLower(uint64_t at, const int64_t origin[3]) {
    for (uint32_t n = 0; n < 4096; ++n) {
      const int64_t o[3] = {origin[0] + int64_t(n >> 8) * kLowerTileVoxels,
                            origin[1] + int64_t((n >> 4) & 15) * kLowerTileVoxels,
                            origin[2] + int64_t(n & 15) * kLowerTileVoxels};
      const uint64_t entry = at + kLowerTableAt + 8 * uint64_t(n);
      const bool isChild = (read<uint32_t>(at + kLowerChildMaskAt + 4 * uint64_t(n >> 5)) >> (n & 31)) & 1;
      if (!isChild) {
        if (touchesBox(o, kLowerTileVoxels)) addCube(o, kLowerTileVoxels, value(entry));
        continue;
      }
      const uint64_t leafAt = child(at, read<int64_t>(entry), leaves_, "leaf");
      if (!touchesBox(o, kLowerTileVoxels)) continue;
      for (uint32_t v = 0; v < 512; ++v) {
        const int64_t x = o[0] + (v >> 6), y = o[1] + ((v >> 3) & 7), z = o[2] + (v & 7);
        if (x < lo_[0] || y < lo_[1] || z < lo_[2] || x >= hi_[0] || y >= hi_[1] || z >= hi_[2]) continue;
        addVoxel(x, y, z, value(leafAt + kLeafValuesAt + 4 * uint64_t(v)));
      }
    }
  }

  const std::vector<uint8_t>& bytes_;
  const std::string& file_;
  const std::string& grid_;
  const NanoVdbValues accepted_;
  NodeLevel upper_, lower_, leaves_;
  int64_t lo_[3] = {0, 0, 0}, hi_[3] = {0, 0, 0};  // the index box, [lo, hi)
  std::vector<AxisCells> axes_;
  float* out_ = nullptr;
};

}  // namespace

NanoVdbDenseGrid appendNanoVdbDenseGrid(const std::vector<uint8_t>& grid, const std::string& file,
                                        const std::string& gridName, uint32_t maxResolution,
                                        std::vector<float>& values) {
  return DenseGridWalk(grid, file, gridName, NanoVdbValues::NotNegative)
      .run(nullptr, std::max<uint32_t>(maxResolution, 1), values);
}

NanoVdbDenseGrid appendNanoVdbDenseGridLike(const std::vector<uint8_t>& grid, const std::string& file,
                                            const std::string& gridName, const NanoVdbDenseGrid& like,
                                            NanoVdbValues accepted, std::vector<float>& values) {
  return DenseGridWalk(grid, file, gridName, accepted).run(&like, 0, values);
}

}  // namespace candela
