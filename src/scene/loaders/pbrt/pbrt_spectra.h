#pragma once
#include <optional>
#include <string>
#include <vector>

#include "core/math.h"

namespace candela {

// pbrt renders spectrally; candela in linear sRGB. These turn pbrt's spectra into sRGB triples.

// A blackbody at `kelvin`, normalised to luminance 1 (as pbrt-v4 normalises light spectra).
Vec3 blackbodyRgb(float kelvin);

// pbrt-v4's BlackbodySpectrum at `kelvin` (Planck's law divided by its value at the peak wavelength, so 1 there, as
// media emit it) in linear sRGB as pbrt-v4's film records an emitted spectrum: its XYZ divided by the integral of
// y, so that a spectrum of 1 at every wavelength has luminance 1. 0 at or below 0 K.
Vec3 peakNormalisedBlackbodyRgb(double kelvin);
// The same at each of `kelvins`, with the colour matching functions evaluated once for all: a table of thousands
// of temperatures in about a quarter of the time.
std::vector<Vec3> peakNormalisedBlackbodyRgbs(const std::vector<double>& kelvins);

// A spectrum sampled at (wavelength in nm, value) pairs, projected onto the sRGB colour matching functions and
// normalised per channel so that a constant spectrum gives a grey of the same value.
Vec3 sampledSpectrumRgb(const std::vector<double>& wavelengthValuePairs);

// pbrt-v4's named spectra: "stdillum-*" illuminants (luminance 1), "metal-*-eta" / "metal-*-k" conductor
// constants and "glass-*" indices of refraction (at their value near 550 nm). Nothing for unknown names.
std::optional<Vec3> namedSpectrumRgb(const std::string& name);
bool isNamedIlluminant(const std::string& name);

// Reflectance at normal incidence of a conductor with complex index eta + i k, per channel.
Vec3 conductorReflectance(Vec3 eta, Vec3 k);

}  // namespace candela
