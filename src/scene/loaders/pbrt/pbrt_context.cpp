#include "scene/loaders/pbrt/pbrt_context.h"

#include <filesystem>

#include "io/load_diagnostics.h"

namespace candela {

PbrtContext::PbrtContext(const std::string& file, LoadWarnings& w, OutsidePaths outside)
    : mainFile(file), rule(PathRule::forFile(file, outside)), warnings(w) {
  baseFolder = rule.folder;
  scene.name = std::filesystem::path(file).stem().string();
  scene.inputFiles.push_back(file);
}

void PbrtContext::warn(const std::string& feature, const std::string& what) {
  if (warnedFeatures.insert(feature).second) warnings.add(mainFile, what);
}

void PbrtContext::warnUnused(const std::string& directive, const PbrtParameters& params) {
  for (const std::string& name : params.unused())
    warn(directive + " " + name, directive + ": parameter '" + name + "' is not applied");
  for (const std::string& spectrum : params.unknownSpectra)
    warn("spectrum " + spectrum, "spectrum '" + spectrum + "' is not known: the parameter's default is used");
}

std::string PbrtContext::resolve(const std::string& reference, const std::string& file, size_t line) {
  if (!filesAllowed) failLoad(file, line, "'" + reference + "': a scene read from memory cannot refer to files");
  ResolvedPath resolved = resolveModelPath(baseFolder, reference, rule);
  if (!resolved.allowed()) failLoad(file, line, resolved.refusal);
  for (const std::string& known : scene.inputFiles)
    if (known == resolved.path) return resolved.path;
  scene.inputFiles.push_back(resolved.path);
  return resolved.path;
}

}  // namespace candela
