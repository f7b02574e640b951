#pragma once
// Heterogeneous media: pbrt-v4's GridMedium (`uniformgrid`; NanoVDBMedium, `nanovdb`, is made one when loaded),
// RGBGridMedium (`rgbgrid`) and CloudMedium (`cloud`). A Medium whose `grid` names a MediumGrid varies over the box
// [p0, p1] of its own space (the transform in effect where the scene defined it) and is vacuum outside; its
// coefficients at a point are the Medium's times the grid's factors there:
//   uniformgrid: sigma_a = Medium::sigmaA x density(p), sigma_s likewise (pbrt's `scale` folded into the Medium),
//                Le = Medium::emission x Lescale(p) (a grid, or 1 where the file gives none);
//   rgbgrid:     sigma_a = Medium::sigmaA x its RGB grid (1 where absent), sigma_s likewise, Le = Medium::emission
//                x its RGB grid (0 where absent); the Medium holds `scale` and `Lescale` as greys;
//   temperature: a uniformgrid or nanovdb grid may carry a temperature grid: Le is then also times the blackbody
//                of (temperature(p) - offset) x scale kelvins, the temperature interpolated first, as pbrt-v4 does
//                (blackbodyEmission below);
//   cloud:       sigma_a and sigma_s times pbrt's procedural density (cloud_density.h), no emission.
// The samples live in the scene's one `mediumGridValues` array; a grid names its pieces by offset. Lookups are
// trilinear between samples at voxel centres and fall to 0 outside them, as pbrt's SampledGrid.
// Each grid also has a majorant grid over the same box (pbrt's MajorantGrid: 16^3 voxels, 1 for the cloud): a
// voxel holds a bound of every channel of sigma_t anywhere inside it, one grey number, which the tracking
// (grid_tracking.h) samples against.
#include <cstdint>

#include "core/math.h"
#include "kernel/media/cloud_density.h"
#include "kernel/media/medium.h"

namespace candela {

// An offset into mediumGridValues that holds nothing: the factor is 1 (sigma) or 0 (emission).
constexpr uint32_t kNoGridValues = 0xffffffffu;

enum class MediumGridKind : uint32_t { Density, Rgb, Cloud };

struct MediumGrid {
  Affine3x4 mediumFromWorld;  // world space to the medium's own
  Vec3 p0{0, 0, 0};           // the box the medium fills, in its own space (pbrt's p0, p1)
  Vec3 p1{1, 1, 1};
  MediumGridKind kind = MediumGridKind::Density;
  uint32_t nx = 1, ny = 1, nz = 1;       // samples per axis (uniformgrid, rgbgrid)
  uint32_t density = kNoGridValues;      // uniformgrid: nx ny nz densities, x fastest
  uint32_t sigmaA = kNoGridValues;       // rgbgrid: 3 floats per sample
  uint32_t sigmaS = kNoGridValues;       // rgbgrid: 3 floats per sample
  uint32_t emission = kNoGridValues;     // uniformgrid: nx ny nz Lescale values; rgbgrid: 3 floats per sample
  uint32_t majorants = kNoGridValues;    // mx my mz grey bounds of sigma_t, x fastest
  uint32_t temperature = kNoGridValues;  // uniformgrid: nx ny nz temperatures as the file gives them
  uint32_t blackbody = kNoGridValues;    // with a temperature: kBlackbodyTableSize RGB emissions (blackbodyEmission)
  float temperatureOffset = 0.0f;        // kelvins = (temperature - offset) x scale (pbrt's temperatureoffset and
  float temperatureScale = 1.0f;         // temperaturescale)
  uint32_t mx = 1, my = 1, mz = 1;       // majorant voxels per axis
  float cloudDensity = 1.0f;             // cloud: pbrt's density, wispiness and frequency
  float wispiness = 1.0f;
  float frequency = 5.0f;
};

// Emission from temperature: pbrt-v4's media emit nothing at or below 100 K and a BlackbodySpectrum (1 at its peak)
// above. Hotter than 1e5 K they glow as at 1e5 K (pbrt evaluates Planck's law in float, whose wavelength^5 at the
// peak leaves float's range about there). The scene holds the blackbody's linear sRGB at 100 K x 2^(i / 512),
// i = 0 to kBlackbodyTableSize - 1 (the last one past 1e5 K: 512 log2(1000) = 5102.4).
constexpr float kBlackbodyCutoffKelvin = 100.0f;
constexpr float kBlackbodyHottestKelvin = 1e5f;
constexpr uint32_t kBlackbodyStepsPerOctave = 512;
constexpr uint32_t kBlackbodyTableSize = 5104;

// pbrt-v4's majorant grid resolution for grid media.
constexpr uint32_t kMajorantGridResolution = 16;

// A medium's coefficients at one point.
struct MediumPoint {
  Vec3 sigmaA;
  Vec3 sigmaS;
  Vec3 emission;  // Le: the source term is sigmaA x emission
};

namespace grid_detail {
CANDELA_FN int floorToInt(float x) { return int(floorf(x)); }
}  // namespace grid_detail

// Trilinear interpolation of a grid of `channels` floats per sample (nx ny nz samples from values[offset]) at p in
// the unit cube, samples at voxel centres, 0 outside (pbrt's SampledGrid::Lookup). Writes `channels` results.
CANDELA_FN void sampleGrid(const float* values, uint32_t offset, uint32_t channels, uint32_t nx, uint32_t ny,
                           uint32_t nz, Vec3 p, float* out) {
  const float sx = p.x * float(nx) - 0.5f, sy = p.y * float(ny) - 0.5f, sz = p.z * float(nz) - 0.5f;
  const int ix = grid_detail::floorToInt(sx), iy = grid_detail::floorToInt(sy), iz = grid_detail::floorToInt(sz);
  const float dx = sx - float(ix), dy = sy - float(iy), dz = sz - float(iz);
  for (uint32_t c = 0; c < channels; ++c) out[c] = 0.0f;
  for (int corner = 0; corner < 8; ++corner) {
    const int x = ix + (corner & 1), y = iy + ((corner >> 1) & 1), z = iz + (corner >> 2);
    if (x < 0 || y < 0 || z < 0 || x >= int(nx) || y >= int(ny) || z >= int(nz)) continue;
    const float w =
        ((corner & 1) ? dx : 1.0f - dx) * (((corner >> 1) & 1) ? dy : 1.0f - dy) * ((corner >> 2) ? dz : 1.0f - dz);
    const float* sample = values + offset + (size_t(uint32_t(z) * ny + uint32_t(y)) * nx + uint32_t(x)) * channels;
    for (uint32_t c = 0; c < channels; ++c) out[c] += w * sample[c];
  }
}

// The RGB emission of a blackbody at `kelvin` from the scene's table (kBlackbodyTableSize entries), interpolated
// between its temperatures: 0 at or below the cutoff (NaN too).
CANDELA_FN Vec3 blackbodyEmission(const float* table, float kelvin) {
  if (!(kelvin > kBlackbodyCutoffKelvin)) return {0.0f, 0.0f, 0.0f};
  const float at =
      log2f(fminf(kelvin, kBlackbodyHottestKelvin) / kBlackbodyCutoffKelvin) * float(kBlackbodyStepsPerOctave);
  const uint32_t i = at < float(kBlackbodyTableSize - 2) ? uint32_t(at) : kBlackbodyTableSize - 2;
  const float f = fminf(at - float(i), 1.0f);
  const float* a = table + 3 * size_t(i);
  return {a[0] + f * (a[3] - a[0]), a[1] + f * (a[4] - a[1]), a[2] + f * (a[5] - a[2])};
}

// A point of world space in the grid's unit cube (0 at p0, 1 at p1).
CANDELA_FN Vec3 gridUnitPoint(const MediumGrid& grid, Vec3 mediumPoint) {
  const Vec3 d = grid.p1 - grid.p0;
  return {(mediumPoint.x - grid.p0.x) / d.x, (mediumPoint.y - grid.p0.y) / d.y, (mediumPoint.z - grid.p0.z) / d.z};
}

// The coefficients of grid medium m at world point p: vacuum outside its box, as pbrt's media are (their lookups
// near the faces would otherwise reach half a voxel beyond them). Called, not inlined, on the device: every tracking
// step and scattering vertex in a grid asks for it.
CANDELA_FN_CALLED MediumPoint gridMediumAt(const Medium& m, const MediumGrid& grid, const float* values, Vec3 p) {
  const Vec3 local = grid.mediumFromWorld.point(p);
  MediumPoint out;
  if (!(local.x >= grid.p0.x && local.y >= grid.p0.y && local.z >= grid.p0.z && local.x <= grid.p1.x &&
        local.y <= grid.p1.y && local.z <= grid.p1.z))
    return out;
  if (grid.kind == MediumGridKind::Cloud) {
    const float d = cloudDensity(local, grid.cloudDensity, grid.wispiness, grid.frequency);
    out.sigmaA = m.sigmaA * d;
    out.sigmaS = m.sigmaS * d;
    return out;
  }
  const Vec3 u = gridUnitPoint(grid, local);
  if (grid.kind == MediumGridKind::Density) {
    float d = 0.0f, le = 1.0f;
    sampleGrid(values, grid.density, 1, grid.nx, grid.ny, grid.nz, u, &d);
    if (grid.emission != kNoGridValues) sampleGrid(values, grid.emission, 1, grid.nx, grid.ny, grid.nz, u, &le);
    out.sigmaA = m.sigmaA * d;
    out.sigmaS = m.sigmaS * d;
    out.emission = m.emission * le;
    if (grid.temperature != kNoGridValues) {
      float t = 0.0f;
      sampleGrid(values, grid.temperature, 1, grid.nx, grid.ny, grid.nz, u, &t);
      out.emission = out.emission *
                     blackbodyEmission(values + grid.blackbody, (t - grid.temperatureOffset) * grid.temperatureScale);
    }
    return out;
  }
  auto rgb = [&](uint32_t offset, float absent) {
    float c[3] = {absent, absent, absent};
    if (offset != kNoGridValues) sampleGrid(values, offset, 3, grid.nx, grid.ny, grid.nz, u, c);
    return Vec3{c[0], c[1], c[2]};
  };
  out.sigmaA = m.sigmaA * rgb(grid.sigmaA, 1.0f);
  out.sigmaS = m.sigmaS * rgb(grid.sigmaS, 1.0f);
  out.emission = m.emission * rgb(grid.emission, 0.0f);
  return out;
}

// The grey majorant of voxel (x, y, z) of the grid's majorant grid.
CANDELA_FN float gridMajorant(const MediumGrid& grid, const float* values, uint32_t x, uint32_t y, uint32_t z) {
  return values[grid.majorants + (z * grid.my + y) * grid.mx + x];
}

}  // namespace candela
