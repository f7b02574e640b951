#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "app/interactive/camera_input.h"
#include "app/interactive/interactive_options.h"
#include "app/interactive/post_settings.h"
#include "scene/material_overrides.h"

namespace candela {

// What a browser may say, as JSON text messages with a "type". Coordinates are in the image's pixels as the
// browser shows it (its view's size is the last "resize").

struct PointerMessage {
  enum class Action { Down, Up, Move };
  Action action = Action::Move;
  MouseButton button = MouseButton::Left;
  double x = 0.0, y = 0.0;
};
struct WheelMessage {
  double steps = 0.0;  // positive towards the target
};
struct KeysMessage {
  FlyKeys held;  // every fly key the browser holds down now
};
struct ResizeMessage {
  uint32_t width = 0, height = 0;
};
struct ActionMessage {
  enum class Kind { Frame, Reset, Screenshot, SaveView, TakeControl };
  Kind kind = Kind::Frame;
};
// The browser has drawn frame `frame`; the server sends it no other frame until then.
struct FrameAckMessage {
  uint64_t frame = 0;
};
// How a browser takes its frames: JPEG stripes, or the H.264 stream where its WebCodecs can decode it.
enum class FrameStream { Jpeg, H264 };
struct StreamMessage {
  FrameStream stream = FrameStream::Jpeg;
};
// The panel's edits; absent fields stay as they are.
struct SettingsMessage {
  std::optional<uint32_t> maxDepth, samplesPerFrame;
  std::optional<bool> accumulate;
  std::optional<float> environmentScale, environmentRotation;
  std::optional<ShadingModel> shading;
  std::vector<std::pair<std::string, std::optional<float>>> overrides;  // name and value, or switched off
  std::optional<float> exposure;
  std::optional<ToneMapper> toneMapper;
  std::optional<DenoiserChoice> denoiser;
  std::optional<int> atrousPasses;
  std::optional<bool> bilateral;
  std::optional<bool> playing;            // the animation plays or pauses
  std::optional<uint32_t> animationClip;  // plays this clip from its start
  std::optional<float> animationTime;     // pauses the animation at this time
};

using ClientMessage = std::variant<PointerMessage, WheelMessage, KeysMessage, ResizeMessage, ActionMessage,
                                   FrameAckMessage, StreamMessage, SettingsMessage>;

// The limits every message is checked against; depth and samples per frame have the command line's
// (interactive_options.h).
constexpr uint32_t kMaxViewSide = 4096;
constexpr uint32_t kMinViewSide = 16;
constexpr double kMaxCoordinate = 1e6;
constexpr double kMaxWheelSteps = 100.0;
constexpr double kMaxAnimationClip = 1e6;
constexpr double kMaxAnimationSeconds = 1e9;

// The message `text` holds, or nullopt with `problem` saying why it is dropped (not JSON, unknown type, a field
// of the wrong kind or out of range). Never throws for any input.
std::optional<ClientMessage> parseClientMessage(std::string_view text, std::string& problem);

// Text a client sent, as a message about it quotes it: at most kMaxQuotedClientBytes of it (then "..."), made
// printable (io/load_diagnostics.h: printableText), so that no client writes escape sequences or long lines to
// the server's terminal.
constexpr size_t kMaxQuotedClientBytes = 40;
std::string quotedClientText(std::string_view text);

// The names the page and the messages use.
const char* streamName(FrameStream stream);  // "jpeg", "h264"

}  // namespace candela
