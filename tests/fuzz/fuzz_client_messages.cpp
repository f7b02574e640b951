// libFuzzer entry point for what a browser sends candela serve (app/serve/client_messages.h): any text must parse
// into a message whose values keep to the limits, or be dropped with a problem that is one printable line quoting
// no more than a few bytes of the text (the server prints it); never crash or hang.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>

#include "app/serve/client_messages.h"
#include "io/load_diagnostics.h"

namespace {

using namespace candela;

// The longest problem: a field name that quotes kMaxQuotedClientBytes of the client's text, every byte escaped.
constexpr size_t kMaxProblemBytes = 64 + 4 * kMaxQuotedClientBytes;

bool within(double value, double lo, double hi) { return std::isfinite(value) && value >= lo && value <= hi; }

template <class T>
bool within(const std::optional<T>& value, double lo, double hi) {
  return !value || within(double(*value), lo, hi);
}

bool keepsToTheLimits(const ClientMessage& message) {
  return std::visit(
      [](const auto& m) {
        using T = std::decay_t<decltype(m)>;
        if constexpr (std::is_same_v<T, PointerMessage>) {
          return within(m.x, -kMaxCoordinate, kMaxCoordinate) && within(m.y, -kMaxCoordinate, kMaxCoordinate);
        } else if constexpr (std::is_same_v<T, WheelMessage>) {
          return within(m.steps, -kMaxWheelSteps, kMaxWheelSteps);
        } else if constexpr (std::is_same_v<T, ResizeMessage>) {
          return within(m.width, kMinViewSide, kMaxViewSide) && within(m.height, kMinViewSide, kMaxViewSide);
        } else if constexpr (std::is_same_v<T, SettingsMessage>) {
          bool ok = within(m.maxDepth, 1, kMaxInteractiveDepth) && within(m.samplesPerFrame, 1, kMaxSamplesPerFrame) &&
                    within(m.environmentScale, 0, 16) && within(m.environmentRotation, -180, 180) &&
                    within(m.exposure, -10, 10) && within(m.animationClip, 0, kMaxAnimationClip) &&
                    within(m.animationTime, -kMaxAnimationSeconds, kMaxAnimationSeconds);
          for (const auto& [name, value] : m.overrides) {
            bool known = false;
            for (const OverrideParameter& p : overrideParameters())
              if (name == p.name) known = !value || within(double(*value), p.min, p.max);
            ok = ok && known;
          }
          return ok;
        } else {
          return true;  // names and numbers whose every value is valid
        }
      },
      message);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string problem;
  const std::optional<ClientMessage> message =
      parseClientMessage(std::string_view(reinterpret_cast<const char*>(data), size), problem);
  if (message && !keepsToTheLimits(*message)) std::abort();
  if (!message && (problem.empty() || problem.size() > kMaxProblemBytes || printableText(problem) != problem))
    std::abort();
  return 0;
}
