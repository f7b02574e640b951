#pragma once
// A NanoVDB float grid turned into a dense grid of samples (the representation of pbrt's uniformgrid,
// kernel/media/medium_grid.h): the voxels of its index bounding box, area-averaged down where the box is larger
// than a bound a side. NanoVDB's tree (a root table of tiles, 32^3 upper nodes, 16^3 lower nodes, 8^3 leaves, as
// NanoVDB 32 lays them out for float values) is walked from the root: every child offset must name a node of its
// level's array inside the grid's bytes, each node is reached once, and tiles add their value over the region
// they stand for, so that the work is bounded by the grid's bytes and the dense grid's size, whatever the file
// claims.
#include <cstdint>
#include <string>
#include <vector>

namespace candela {

struct NanoVdbDenseGrid {
  uint32_t nx = 0, ny = 0, nz = 0;  // samples per axis, at most the bound
  int32_t indexMin[3] = {0, 0, 0};  // the index bounding box of the grid's active voxels, inclusive
  int32_t indexMax[3] = {0, 0, 0};
  // NanoVDB's map from index space to the grid's world space, row by row: world = m[0..2] . index + m[3], ...
  double worldFromIndex[12] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
  bool downsampled = false;  // some axis had more voxels than the bound
  uint64_t offset = 0;       // where its nx ny nz samples (x fastest) begin in the values appended to
};

// The values a grid may hold: a density's are finite and not negative, a temperature's finite.
enum class NanoVdbValues { NotNegative, Finite };

// Appends the dense samples of the float grid in `grid` (the bytes of one grid, NanoVdbFile::gridBytes) to
// `values`, charged to the load's memory budget before they are allocated. Sample (i, j, k) is the average of the
// voxels of the index box's cell (i, j, k) when the box is cut into nx ny nz equal cells; without downsampling it
// is the value of voxel indexMin + (i, j, k), NanoVDB's value at that voxel's centre. Throws LoadError naming
// `file` and `gridName` for anything out of place: a grid of another value type, a node or offset outside the
// grid's bytes, an empty or absurdly large bounding box (over 2^20 voxels a side), a map that cannot be inverted,
// a negative or non-finite value.
NanoVdbDenseGrid appendNanoVdbDenseGrid(const std::vector<uint8_t>& grid, const std::string& file,
                                        const std::string& gridName, uint32_t maxResolution,
                                        std::vector<float>& values);

// The same for a second grid of a file, sampled over the cells of the first one's dense grid `like`: the same index
// box cut into the same nx ny nz cells whatever the grid's own box, the grid's background where it has no voxels.
// The result states `like`'s box and size and the grid's own index-to-world map, which the caller compares with
// `like`'s. Values are checked as `accepted` says.
NanoVdbDenseGrid appendNanoVdbDenseGridLike(const std::vector<uint8_t>& grid, const std::string& file,
                                            const std::string& gridName, const NanoVdbDenseGrid& like,
                                            NanoVdbValues accepted, std::vector<float>& values);

}  // namespace candela
