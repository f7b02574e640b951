#include "app/checkpoint/render_identity.h"

#include <xxhash.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <tuple>
#include <vector>

#include "scene/material_overrides.h"

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

std::string overridesText(const MaterialOverrides& overrides) {
  std::string text = std::string("shading=") + shadingModelName(overrides.shading);
  for (const OverrideParameter& p : overrideParameters())
    if (const std::optional<float>& value = overrides.*p.field) {
      char number[32];
      std::snprintf(number, sizeof number, "%.9g", double(*value));
      text += std::string(" ") + p.name + "=" + number;
    }
  return text;
}

// XXH3 of a file's contents as 16 hexadecimal digits, or "unreadable". Remembered by path, size and modification
// time, so that the frames of a sequence read each file once.
std::string contentHash(const std::string& path) {
  std::error_code error;
  const uintmax_t size = std::filesystem::file_size(path, error);
  const auto modified = std::filesystem::last_write_time(path, error);
  if (error) return "unreadable";
  using Key = std::tuple<std::string, uintmax_t, std::filesystem::file_time_type>;
  static std::map<Key, std::string> known;
  const Key key{path, size, modified};
  if (const auto it = known.find(key); it != known.end()) return it->second;
  std::ifstream in(path, std::ios::binary);
  std::unique_ptr<XXH3_state_t, decltype(&XXH3_freeState)> state(XXH3_createState(), &XXH3_freeState);
  XXH3_64bits_reset(state.get());
  std::vector<char> buffer(size_t(1) << 20);
  while (in) {
    in.read(buffer.data(), std::streamsize(buffer.size()));
    XXH3_64bits_update(state.get(), buffer.data(), size_t(in.gcount()));
  }
  if (in.bad()) return "unreadable";
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(XXH3_64bits_digest(state.get())));
  return known[key] = hex;
}

}  // namespace

ExrAttributes teamIdentity(const RenderJob& job, const Scene& scene, bool withAovs) {
  ExrAttributes identity = renderIdentity(job, withAovs);
  for (auto& [name, value] : identity) {
    if (name == "candela.scene" && !scene.inputFiles.empty()) {
      value = "files";
      for (const std::string& file : scene.inputFiles) {
        value += ' ';
        value += contentHash(file);
      }
    } else if (name == "candela.environment" && !job.environmentPath.empty()) {
      value = "file ";
      value += contentHash(job.environmentPath);
    }
  }
  return identity;
}

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
