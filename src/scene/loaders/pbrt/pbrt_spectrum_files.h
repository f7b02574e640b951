#pragma once
#include <string>
#include <vector>

#include "scene/loaders/pbrt/pbrt_context.h"
#include "scene/loaders/pbrt/pbrt_parameters.h"

namespace candela {

// The largest spectrum file read: measured spectra are a few kilobytes of text.
constexpr size_t kMaxSpectrumFileBytes = size_t(1) << 20;

// The wavelength-value pairs of a pbrt spectrum file (`.spd`): numbers separated by white space, `#` comments to
// the end of the line. Throws LoadError naming `path` (and the line) when it holds anything else, no pairs, or an
// odd count of numbers.
std::vector<double> parsePbrtSpectrumFile(const std::string& path, const std::string& text);

// pbrt-v4 reads a `spectrum` parameter that names no spectrum it knows as a file of wavelength-value pairs, relative
// to the scene's folder. Each such parameter of `params` becomes those pairs; a file that cannot be read or
// parsed is a warning, and the parameter is left for the lookups to report and replace by its default.
void readPbrtSpectrumFiles(PbrtParameters& params, PbrtContext& context);

}  // namespace candela
