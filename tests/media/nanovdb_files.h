#pragma once
// NanoVDB files for tests/media, written as NanoVDB 32's io::writeGrid writes them (a segment header, each grid's
// 176-byte description and name, then each grid: GridData, TreeData, the root and its tiles, upper nodes, lower
// nodes, leaves), from a box of voxels given densely.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace candela::test {

struct TestNanoVdbGrid {
  std::string name = "density";
  uint32_t valueType = 1;                  // float
  uint32_t gridClass = 2;                  // fog volume
  std::array<int32_t, 3> origin{0, 0, 0};  // index coordinates of the box's first voxel
  std::array<uint32_t, 3> size{1, 1, 1};   // voxels a side
  std::vector<float> values;               // size[0] size[1] size[2], x fastest
  float background = 0.0f;
  // NanoVDB's map, index to world: per axis scale and translation.
  std::array<double, 3> voxelSize{1, 1, 1};
  std::array<double, 3> translation{0, 0, 0};
};

// The grid's bytes (GridData onwards). A leaf whose 512 voxels are all one value becomes a tile of its lower
// node, as NanoVDB's builder prunes it.
std::vector<uint8_t> nanoVdbGridBytes(const TestNanoVdbGrid& grid);

// A .nvdb file of one segment holding `grids`; `zip` compresses each grid with zlib (NanoVDB's ZIP codec).
std::string nanoVdbFile(const std::vector<TestNanoVdbGrid>& grids, bool zip = false);

// Where the first grid's bytes begin in a file of one segment whose first grid is named `name`.
inline size_t firstGridOffset(const std::string& name) { return 16 + 176 + name.size() + 1; }

}  // namespace candela::test
