#pragma once
#include <cstddef>
#include <set>
#include <string>

#include "io/load_diagnostics.h"
#include "io/path_confinement.h"
#include "scene/loaders/pbrt/pbrt_parameters.h"
#include "scene/scene.h"

namespace candela {

// What every part of the pbrt loader shares: the scene being built, where referenced files may be, and the
// warnings (one per feature, however often a scene uses it).
struct PbrtContext {
  std::string mainFile;
  std::string baseFolder;  // pbrt resolves every relative path against the folder of the file it was started on
  PathRule rule;
  Scene scene;
  LoadWarnings& warnings;
  std::set<std::string> warnedFeatures;
  bool filesAllowed = true;  // false for a scene read from memory: it may name no files

  PbrtContext(const std::string& file, LoadWarnings& w, OutsidePaths outside);

  void warn(const std::string& feature, const std::string& what);
  // One warning for each parameter of `directive` (a shape, material, light... type) that was not applied, and
  // for each spectrum its colours could not be read from.
  void warnUnused(const std::string& directive, const PbrtParameters& params);
  // The file a scene refers to, confined to baseFolder's tree unless allowed otherwise, and recorded among the
  // scene's inputs. Throws LoadError naming `file:line` when the reference is refused.
  std::string resolve(const std::string& reference, const std::string& file, size_t line);
};

}  // namespace candela
