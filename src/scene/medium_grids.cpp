#include "scene/medium_grids.h"

#include <algorithm>
#include <cmath>

namespace candela {

namespace {

// The sample indices along one axis of n samples whose trilinear lookups reach into [lo, hi] of the unit interval
// (pbrt-v4's SampledGrid::MaxValue): samples sit at voxel centres, (i + 0.5) / n.
void sampleRange(float lo, float hi, uint32_t n, uint32_t& first, uint32_t& last) {
  first = uint32_t(std::max(0.0f, std::floor(lo * float(n) - 0.5f)));
  last = uint32_t(std::clamp(std::floor(hi * float(n) - 0.5f) + 1.0f, 0.0f, float(n - 1)));
  first = std::min(first, last);
}

// The largest channel of sigma_t at sample i.
float sampleSigmaT(const Medium& m, const MediumGrid& grid, const std::vector<float>& values, size_t i) {
  if (grid.kind == MediumGridKind::Density) return values[grid.density + i] * maxComponent(m.sigmaA + m.sigmaS);
  auto rgb = [&](uint32_t offset) {
    if (offset == kNoGridValues) return Vec3{1, 1, 1};
    const float* v = values.data() + offset + 3 * i;
    return Vec3{v[0], v[1], v[2]};
  };
  return maxComponent(m.sigmaA * rgb(grid.sigmaA) + m.sigmaS * rgb(grid.sigmaS));
}

}  // namespace

void buildMajorantGrid(const Medium& m, MediumGrid& grid, std::vector<float>& values) {
  if (grid.kind == MediumGridKind::Cloud) {
    grid.mx = grid.my = grid.mz = 1;
    grid.majorants = uint32_t(values.size());
    values.push_back(maxComponent(m.sigmaA + m.sigmaS));
    return;
  }
  grid.mx = grid.my = grid.mz = kMajorantGridResolution;
  std::vector<float> majorants(size_t(grid.mx) * grid.my * grid.mz);
  for (uint32_t z = 0; z < grid.mz; ++z)
    for (uint32_t y = 0; y < grid.my; ++y)
      for (uint32_t x = 0; x < grid.mx; ++x) {
        uint32_t x0, x1, y0, y1, z0, z1;
        sampleRange(float(x) / float(grid.mx), float(x + 1) / float(grid.mx), grid.nx, x0, x1);
        sampleRange(float(y) / float(grid.my), float(y + 1) / float(grid.my), grid.ny, y0, y1);
        sampleRange(float(z) / float(grid.mz), float(z + 1) / float(grid.mz), grid.nz, z0, z1);
        float bound = 0.0f;
        for (uint32_t sz = z0; sz <= z1; ++sz)
          for (uint32_t sy = y0; sy <= y1; ++sy)
            for (uint32_t sx = x0; sx <= x1; ++sx)
              bound = std::max(bound, sampleSigmaT(m, grid, values, (size_t(sz) * grid.ny + sy) * grid.nx + sx));
        majorants[(size_t(z) * grid.my + y) * grid.mx + x] = bound;
      }
  grid.majorants = uint32_t(values.size());
  values.insert(values.end(), majorants.begin(), majorants.end());
}

std::string mediumGridProblem(const MediumGrid& grid, const std::vector<float>& values) {
  if (grid.kind != MediumGridKind::Density && grid.kind != MediumGridKind::Rgb && grid.kind != MediumGridKind::Cloud)
    return "a medium grid of unknown kind";
  for (float v : grid.mediumFromWorld.m)
    if (!std::isfinite(v)) return "a medium grid with a non-finite transform";
  const Vec3 extent = grid.p1 - grid.p0;
  if (!isFinite(grid.p0) || !isFinite(grid.p1) || !(extent.x > 0.0f && extent.y > 0.0f && extent.z > 0.0f))
    return "a medium grid whose box is empty or not finite";
  if (!std::isfinite(grid.cloudDensity) || !std::isfinite(grid.wispiness) || !std::isfinite(grid.frequency))
    return "a cloud medium with non-finite parameters";
  if (!std::isfinite(grid.temperatureOffset) || !std::isfinite(grid.temperatureScale))
    return "a medium grid with a non-finite temperature offset or scale";
  // Each piece of samples must lie inside the values, and all but temperatures be at least 0.
  const size_t valueCount = values.size();
  auto fits = [&](uint32_t offset, uint64_t count) {
    return offset == kNoGridValues || (count <= valueCount && offset <= valueCount - count);
  };
  auto negative = [&](uint32_t offset, uint64_t count) {
    return offset != kNoGridValues &&
           std::any_of(values.begin() + offset, values.begin() + offset + count, [](float v) { return v < 0.0f; });
  };
  if (grid.nx == 0 || grid.ny == 0 || grid.nz == 0) return "a medium grid without samples";
  const uint64_t samples = uint64_t(grid.nx) * grid.ny * grid.nz;
  const uint64_t emissionCount = (grid.kind == MediumGridKind::Rgb ? 3 : 1) * samples;
  const uint64_t tableCount = 3 * uint64_t(kBlackbodyTableSize);
  if (!fits(grid.density, samples) || !fits(grid.sigmaA, 3 * samples) || !fits(grid.sigmaS, 3 * samples) ||
      !fits(grid.emission, emissionCount) || !fits(grid.temperature, samples) || !fits(grid.blackbody, tableCount))
    return "a medium grid names samples past the scene's";
  if (grid.kind == MediumGridKind::Density && grid.density == kNoGridValues) return "a density grid without densities";
  if ((grid.temperature == kNoGridValues) != (grid.blackbody == kNoGridValues) ||
      (grid.temperature != kNoGridValues && grid.kind != MediumGridKind::Density))
    return "a medium grid with temperatures but no blackbody table, or the other way round";
  if (grid.mx == 0 || grid.my == 0 || grid.mz == 0 || grid.majorants == kNoGridValues ||
      !fits(grid.majorants, uint64_t(grid.mx) * grid.my * grid.mz))
    return "a medium grid without its majorant grid";
  if (negative(grid.density, samples) || negative(grid.sigmaA, 3 * samples) || negative(grid.sigmaS, 3 * samples) ||
      negative(grid.emission, emissionCount) || negative(grid.blackbody, tableCount) ||
      negative(grid.majorants, uint64_t(grid.mx) * grid.my * grid.mz))
    return "a medium grid has a negative sample";
  return "";
}

std::string mediumGridValuesProblem(const std::vector<float>& values) {
  for (float v : values)
    if (!std::isfinite(v)) return "a medium grid has a non-finite sample";
  return "";
}

}  // namespace candela
