#pragma once
// Emission from temperature, as pbrt-v4's NanoVDBMedium and GridMedium compute it at a point: the temperature t
// interpolated from the grid becomes T = (t - offset) x scale kelvins; at or below 100 K the medium emits nothing,
// above it Le is pbrt's BlackbodySpectrum at T (1 at its peak wavelength; pbrt_spectra.h) times `Lescale`. The
// kernel does that at every point (kernel/media/medium_grid.h: blackbodyEmission) from the grid's temperatures and
// a table of the blackbody's colours that the scene holds once.
#include <cstdint>
#include <string>

#include "scene/loaders/pbrt/pbrt_parameters.h"
#include "scene/scene.h"

namespace candela {

// How a medium's temperatures map to kelvins: pbrt-v4's `temperatureoffset` (which defaults to
// `temperaturecutoff`) and `temperaturescale`.
struct TemperatureToKelvin {
  float offset = 0.0f;
  float scale = 1.0f;
  double operator()(double temperature) const { return (temperature - double(offset)) * double(scale); }
};

// A medium's `temperatureoffset` (default: its `temperaturecutoff`, default 0, as pbrt-v4 reads them: the cutoff is
// no cutoff) and `temperaturescale` (default 1).
TemperatureToKelvin readTemperatureToKelvin(const PbrtParameters& params);

// Makes `grid`, medium `name`'s density grid, emit from its temperatures: its nx ny nz samples, the last of the
// scene's grid values from `offset`, charged to the load's budget. Where some temperature, or the 0 that lookups
// take beyond the samples (mixed in within half a voxel of the box's faces), is hotter than the cutoff after
// offset and scale, the grid takes them, the offset and scale, and the scene's blackbody table (appended the first
// time a grid needs it), and this returns true. Otherwise the medium is dark everywhere, since interpolation stays
// between those values: the temperatures are taken back out of the scene and the budget, and this returns false.
bool emitFromTemperature(const PbrtParameters& params, const std::string& name, uint32_t offset,
                         const TemperatureToKelvin& toKelvin, MediumGrid& grid, Scene& scene);

// The blackbody table's entry i (linear sRGB of 100 K x 2^(i / 512): kernel/media/medium_grid.h).
Vec3 blackbodyTableEntry(uint32_t i);

}  // namespace candela
