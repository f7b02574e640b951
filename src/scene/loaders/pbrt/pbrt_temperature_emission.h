#pragma once
// Emission from temperature, as pbrt-v4's NanoVDBMedium and GridMedium compute it at a point: the temperature t read
// from the grid becomes T = (t - offset) x scale kelvins; at or below 100 K the medium emits nothing, above it Le is
// pbrt's BlackbodySpectrum at T (1 at its peak wavelength; pbrt_spectra.h) times `Lescale`. candela turns each sample
// of the grid into its RGB emission once, when the scene is loaded.
#include "core/math.h"
#include "scene/loaders/pbrt/pbrt_parameters.h"

namespace candela {

// pbrt-v4's cutoff: a medium at or below this temperature (after offset and scale) emits nothing.
constexpr double kEmissionCutoffKelvin = 100.0;
// The hottest temperature whose blackbody is evaluated: hotter samples, up to the largest float and beyond, glow as
// a blackbody of this temperature does (pbrt-v4 evaluates Planck's law in float, whose wavelength^5 at the peak
// leaves float's normal range about here). Its peak lies at 29 nm: its emission in the visible is faint and blue.
constexpr double kEmissionMaxKelvin = 1e5;

// How a medium's temperatures map to kelvins: pbrt-v4's `temperatureoffset` (which defaults to
// `temperaturecutoff`) and `temperaturescale`.
struct TemperatureToKelvin {
  double offset = 0.0;
  double scale = 1.0;
  double operator()(float temperature) const { return (double(temperature) - offset) * scale; }
};

// A medium's `temperatureoffset` (default: its `temperaturecutoff`, default 0, as pbrt-v4 reads them: the cutoff is
// no cutoff) and `temperaturescale` (default 1).
TemperatureToKelvin readTemperatureToKelvin(const PbrtParameters& params);

// The linear sRGB emission (before `Lescale`) of a blackbody at `kelvin`: 0 at or below the cutoff, the
// blackbody at kEmissionMaxKelvin above that, else pbrt's blackbody, interpolated in a table of 512 temperatures
// per octave (built once, within 1e-4 of peakNormalisedBlackbodyRgb where the emission is not negligible).
Vec3 temperatureEmissionRgb(double kelvin);

}  // namespace candela
