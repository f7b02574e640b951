#pragma once
#include <string>

#include "io/load_diagnostics.h"
#include "io/path_confinement.h"
#include "scene/scene.h"

namespace candela {

// Loads a pbrt-v4 scene file (and pbrt-v3 files where the two agree): its Includes and Imports, transforms,
// attributes, object instances, camera, film resolution, sampler and integrator settings (as render hints),
// shapes, materials, textures and lights, turned into candela's models as docs/pbrt-v4.md describes. Features
// candela does not render give one warning each. Files it names must lie in its folder unless `outside` allows
// others. Errors throw LoadError naming the file and line: "scene.pbrt:12: unknown directive 'Shpe'".
Scene loadPbrt(const std::string& path, LoadWarnings& warnings, OutsidePaths outside = OutsidePaths::Refused);

// The same for pbrt text in memory (no Include or files it names may be read); `name` stands for the file.
Scene loadPbrtText(const std::string& name, const std::string& text, LoadWarnings& warnings);

}  // namespace candela
