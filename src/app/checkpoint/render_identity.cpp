#include "app/checkpoint/render_identity.h"

#include <cstdio>
#include <filesystem>

namespace candela {

namespace {

// A file as an absolute path, so that a resumption from another folder finds it the same; a built-in scene's
// name, which is no file, as is.
std::string fileIdentity(const std::string& spec) {
  std::error_code ec;
  if (spec.empty() || !std::filesystem::exists(spec, ec)) return spec;
  const std::filesystem::path absolute = std::filesystem::weakly_canonical(spec, ec);
  return ec ? spec : absolute.string();
}

std::string shadingName(ShadingModel model) {
  switch (model) {
    case ShadingModel::BlinnPhong: return "phong";
    case ShadingModel::Pbr: return "pbr";
    case ShadingModel::Disney: return "disney";
    case ShadingModel::Own: break;
  }
  return "own";
}

std::string overridesText(const MaterialOverrides& overrides) {
  std::string text = "shading=" + shadingName(overrides.shading);
  for (const OverrideParameter& p : overrideParameters())
    if (const std::optional<float>& value = overrides.*p.field) {
      char number[32];
      std::snprintf(number, sizeof number, "%.9g", double(*value));
      text += std::string(" ") + p.name + "=" + number;
    }
  return text;
}

}  // namespace

ExrAttributes renderIdentity(const RenderJob& job, bool withAovs) {
  const RenderSettings& s = job.settings;
  return {
      {"candela.scene", fileIdentity(job.sceneSpec)},
      {"candela.environment", fileIdentity(job.environmentPath)},
      {"candela.camera", job.camera},
      {"candela.width", std::to_string(s.width)},
      {"candela.height", std::to_string(s.height)},
      {"candela.maxDepth", std::to_string(s.maxDepth)},
      {"candela.rouletteDepth", std::to_string(s.rouletteDepth)},
      {"candela.seed", std::to_string(s.seed)},
      {"candela.sampler", s.sampler == SamplerKind::Sobol ? "sobol" : "independent"},
      {"candela.materials", overridesText(job.materialOverrides)},
      {"candela.textureLimits",
       std::to_string(job.textureLimits.maxSize) + " px, " + std::to_string(job.textureLimits.maxBytes) + " bytes"},
      {"candela.outsidePaths", job.outsidePaths == OutsidePaths::Allowed ? "allowed" : "refused"},
      {"candela.aovSums", withAovs ? "yes" : "no"},
  };
}

}  // namespace candela
