#include "scene/loaders/pbrt/pbrt_media.h"

#include <cmath>

#include "io/load_diagnostics.h"
#include "scene/loaders/pbrt/pbrt_grid_media.h"

namespace candela {

namespace {

// pbrt-v4's HomogeneousMedium::Create: sigma_a and sigma_s (default 1 each) times `scale`, emission Le times
// Lescale, asymmetry g. The RGB of Le is taken as it is, as area lights' L is (pbrt_lights.cpp).
Medium homogeneousMedium(const PbrtParameters& params) {
  auto colour = [&](const char* name, Vec3 fallback) {
    std::optional<PbrtColor> c = params.getColor(name);
    Vec3 v = c ? c->rgb : fallback;
    if (!isFinite(v) || v.x < 0.0f || v.y < 0.0f || v.z < 0.0f)
      params.fail(std::string("medium: '") + name + "' must be finite and not negative");
    return v;
  };
  const float scale = params.getFloat("scale", 1.0f);
  if (!(scale >= 0.0f) || !std::isfinite(scale)) params.fail("medium: 'scale' must be finite and not negative");
  const float leScale = params.getFloat("Lescale", 1.0f);
  if (!(leScale >= 0.0f) || !std::isfinite(leScale)) params.fail("medium: 'Lescale' must be finite and not negative");
  const float g = params.getFloat("g", 0.0f);
  if (!(std::fabs(g) < 1.0f)) params.fail("medium: 'g' must lie between -1 and 1");
  Medium m;
  m.sigmaA = colour("sigma_a", {1, 1, 1}) * scale;
  m.sigmaS = colour("sigma_s", {1, 1, 1}) * scale;
  m.emission = colour("Le", {0, 0, 0}) * leScale;
  m.g = g;
  if (!isFinite(m.sigmaA) || !isFinite(m.sigmaS) || !isFinite(m.emission))
    params.fail("medium: its coefficients or emission overflow");
  return m;
}

}  // namespace

uint32_t PbrtMedia::slotOf(const std::string& name) {
  auto [found, added] = byName_.try_emplace(name, uint32_t(slots_.size()));
  if (added) {
    slots_.emplace_back();
    slots_.back().name = name;
  }
  return found->second;
}

void PbrtMedia::define(const std::string& name, const PbrtParameters& params, const glm::mat4& worldFromMedium) {
  const std::string type = params.getString("type", "");
  if (name.empty()) params.fail("MakeNamedMedium: a medium needs a name");
  Slot& slot = slots_[slotOf(name)];
  if (slot.defined) context_.warn("medium " + name, "medium '" + name + "' is defined again: the last one is used");
  slot.defined = true;
  if (type.empty()) params.fail("MakeNamedMedium '" + name + "' needs a \"string type\"");
  if (type != "homogeneous" && !isPbrtGridMedium(type))
    params.fail("MakeNamedMedium: unknown medium type '" + type + "'");
  if (isPbrtGridMedium(type)) {
    slot.medium = readPbrtGridMedium(type, name, params, worldFromMedium, context_);
    return;
  }
  if (params.find("preset"))
    context_.warn("medium preset", "medium presets are not applied: 'sigma_a' and 'sigma_s' (or their defaults) are");
  slot.medium = homogeneousMedium(params);
}

uint32_t PbrtMedia::slot(const std::string& name, const std::string& file, size_t line) {
  if (name.empty()) return kNoMedium;
  Slot& slot = slots_[slotOf(name)];
  if (slot.file.empty()) {
    slot.file = file;
    slot.line = line;
  }
  return byName_.at(name);
}

std::vector<uint32_t> PbrtMedia::finish(Scene& scene) {
  std::vector<uint32_t> index(slots_.size());
  for (size_t i = 0; i < slots_.size(); ++i) {
    const Slot& slot = slots_[i];
    if (!slot.defined) failLoad(slot.file, slot.line, "medium '" + slot.name + "' is not defined");
    index[i] = uint32_t(scene.media.size());
    scene.media.push_back(slot.medium);
  }
  return index;
}

}  // namespace candela
