#include "app/serve/client_messages.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <iterator>
#include <span>
#include <string_view>

#include "io/load_diagnostics.h"

namespace candela {

namespace {

using Json = nlohmann::json;

// A field's checks: each returns false (with `problem` set) when the field is present but unusable.
struct Reader {
  const Json& json;
  std::string& problem;

  bool fail(const std::string& field, const char* why) {
    problem = "field '" + field + "' " + why;
    return false;
  }
  bool number(const char* field, double lo, double hi, std::optional<double>& out) {
    if (!json.contains(field)) return true;
    const Json& v = json[field];
    if (!v.is_number() || !std::isfinite(v.get<double>())) return fail(field, "is not a finite number");
    const double d = v.get<double>();
    if (d < lo || d > hi) return fail(field, "is out of range");
    out = d;
    return true;
  }
  bool requiredNumber(const char* field, double lo, double hi, double& out) {
    std::optional<double> v;
    if (!number(field, lo, hi, v)) return false;
    if (!v) return fail(field, "is missing");
    out = *v;
    return true;
  }
  bool integer(const char* field, double lo, double hi, std::optional<uint32_t>& out) {
    std::optional<double> v;
    if (!number(field, lo, hi, v)) return false;
    if (v && *v != std::floor(*v)) return fail(field, "is not a whole number");
    if (v) out = uint32_t(*v);
    return true;
  }
  bool floating(const char* field, double lo, double hi, std::optional<float>& out) {
    std::optional<double> v;
    if (!number(field, lo, hi, v)) return false;
    if (v) out = float(*v);
    return true;
  }
  bool boolean(const char* field, std::optional<bool>& out) {
    if (!json.contains(field)) return true;
    if (!json[field].is_boolean()) return fail(field, "is not true or false");
    out = json[field].get<bool>();
    return true;
  }
  // One of `names`, as its index.
  bool choice(const char* field, std::span<const char* const> names, std::optional<int>& out) {
    if (!json.contains(field)) return true;
    if (!json[field].is_string()) return fail(field, "is not a string");
    const std::string value = json[field].get<std::string>();
    for (size_t i = 0; i < names.size(); ++i)
      if (value == names[i]) {
        out = int(i);
        return true;
      }
    return fail(field, "names no known choice");
  }
};

constexpr const char* kToneMapperNames[] = {"aces", "clamp", "reinhard"};  // ToneMapper's order
constexpr const char* kDenoiserNames[] = {"none", "atrous", "optix"};      // kViewerDenoiserChoices' order
static_assert(std::size(kDenoiserNames) == std::size(kViewerDenoiserChoices));
static_assert(std::string_view(kDenoiserNames[1]) == denoiserName(kViewerDenoiserChoices[1]) &&
              std::string_view(kDenoiserNames[2]) == denoiserName(kViewerDenoiserChoices[2]));
constexpr const char* kButtonNames[] = {"left", "right", "middle"};  // MouseButton's order
constexpr const char* kPointerActions[] = {"down", "up", "move"};
constexpr const char* kActionNames[] = {"frame", "reset", "screenshot", "save_view", "take_control"};
constexpr const char* kStreamNames[] = {"jpeg", "h264"};  // in the order of FrameStream

std::optional<ClientMessage> pointer(Reader& r) {
  PointerMessage m;
  std::optional<int> action, button;
  if (!r.choice("action", kPointerActions, action) || !r.choice("button", kButtonNames, button) ||
      !r.requiredNumber("x", -kMaxCoordinate, kMaxCoordinate, m.x) ||
      !r.requiredNumber("y", -kMaxCoordinate, kMaxCoordinate, m.y))
    return std::nullopt;
  if (!action) return r.fail("action", "is missing"), std::nullopt;
  m.action = PointerMessage::Action(*action);
  m.button = MouseButton(button.value_or(0));
  return m;
}

std::optional<ClientMessage> keys(Reader& r) {
  KeysMessage m;
  std::optional<bool> forward, back, left, right, down, up;
  if (!r.boolean("forward", forward) || !r.boolean("back", back) || !r.boolean("left", left) ||
      !r.boolean("right", right) || !r.boolean("down", down) || !r.boolean("up", up))
    return std::nullopt;
  m.held = {forward.value_or(false), back.value_or(false), left.value_or(false),
            right.value_or(false),   down.value_or(false), up.value_or(false)};
  return m;
}

bool overrides(Reader& r, SettingsMessage& m) {
  if (!r.json.contains("overrides")) return true;
  const Json& o = r.json["overrides"];
  if (!o.is_object()) return r.fail("overrides", "is not an object");
  for (const auto& [name, value] : o.items()) {
    const OverrideParameter* parameter = nullptr;
    for (const OverrideParameter& p : overrideParameters())
      if (name == p.name) parameter = &p;
    if (!parameter) return r.fail("overrides." + quotedClientText(name), "names no material parameter");
    if (value.is_null()) {
      m.overrides.emplace_back(name, std::nullopt);
      continue;
    }
    if (!value.is_number() || !std::isfinite(value.get<double>()))
      return r.fail("overrides." + name, "is not a number");
    const double v = value.get<double>();
    if (v < parameter->min || v > parameter->max) return r.fail("overrides." + name, "is out of range");
    m.overrides.emplace_back(name, float(v));
  }
  return true;
}

std::optional<ClientMessage> settings(Reader& r) {
  SettingsMessage m;
  std::optional<uint32_t> passes;
  std::optional<int> shading, toneMapper, denoiser;
  if (!r.integer("max_depth", 1, kMaxInteractiveDepth, m.maxDepth) ||
      !r.integer("samples_per_frame", 1, kMaxSamplesPerFrame, m.samplesPerFrame) ||
      !r.boolean("accumulate", m.accumulate) || !r.floating("env_intensity", 0.0, 16.0, m.environmentScale) ||
      !r.floating("env_rotation", -180.0, 180.0, m.environmentRotation) ||
      !r.choice("shading", shadingModelNames(), shading) || !overrides(r, m) ||
      !r.floating("exposure", -10.0, 10.0, m.exposure) || !r.choice("tonemap", kToneMapperNames, toneMapper) ||
      !r.choice("denoiser", kDenoiserNames, denoiser) || !r.integer("atrous_passes", 1, kMaxAtrousPasses, passes) ||
      !r.boolean("bilateral", m.bilateral) || !r.boolean("playing", m.playing) ||
      !r.integer("animation", 0, kMaxAnimationClip, m.animationClip) ||
      !r.floating("animation_time", -kMaxAnimationSeconds, kMaxAnimationSeconds, m.animationTime))
    return std::nullopt;
  if (shading) m.shading = ShadingModel(*shading);
  if (toneMapper) m.toneMapper = ToneMapper(*toneMapper);
  if (denoiser) m.denoiser = kViewerDenoiserChoices[*denoiser];
  if (passes) m.atrousPasses = int(*passes);
  return m;
}

}  // namespace

const char* streamName(FrameStream stream) { return kStreamNames[int(stream)]; }

std::string quotedClientText(std::string_view text) {
  if (text.size() <= kMaxQuotedClientBytes) return printableText(text);
  return printableText(text.substr(0, kMaxQuotedClientBytes)) + "...";
}

std::optional<ClientMessage> parseClientMessage(std::string_view text, std::string& problem) {
  const Json json = Json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (json.is_discarded()) return problem = "not JSON", std::nullopt;
  if (!json.is_object() || !json.contains("type") || !json["type"].is_string())
    return problem = "not an object with a \"type\" string", std::nullopt;
  const std::string type = json["type"].get<std::string>();
  Reader r{json, problem};
  if (type == "pointer") return pointer(r);
  if (type == "keys") return keys(r);
  if (type == "settings") return settings(r);
  if (type == "wheel") {
    WheelMessage m;
    if (!r.requiredNumber("steps", -kMaxWheelSteps, kMaxWheelSteps, m.steps)) return std::nullopt;
    return m;
  }
  if (type == "resize") {
    std::optional<uint32_t> width, height;
    if (!r.integer("width", kMinViewSide, kMaxViewSide, width) ||
        !r.integer("height", kMinViewSide, kMaxViewSide, height))
      return std::nullopt;
    if (!width || !height) return problem = "resize needs a width and a height", std::nullopt;
    return ResizeMessage{*width, *height};
  }
  if (type == "action") {
    std::optional<int> kind;
    if (!r.choice("name", kActionNames, kind)) return std::nullopt;
    if (!kind) return problem = "action needs a name", std::nullopt;
    return ActionMessage{ActionMessage::Kind(*kind)};
  }
  if (type == "frame_ack") {
    std::optional<double> frame;
    if (!r.number("frame", 0.0, 9.0e15, frame)) return std::nullopt;
    if (!frame) return problem = "frame_ack needs a frame", std::nullopt;
    return FrameAckMessage{uint64_t(*frame)};
  }
  if (type == "stream") {
    std::optional<int> stream;
    if (!r.choice("codec", kStreamNames, stream)) return std::nullopt;
    if (!stream) return problem = "stream needs a codec", std::nullopt;
    return StreamMessage{FrameStream(*stream)};
  }
  problem = "unknown type '" + quotedClientText(type) + "'";
  return std::nullopt;
}

}  // namespace candela
