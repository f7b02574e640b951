#include "app/interactive/interactive_policy.h"

#include <algorithm>
#include <cmath>

namespace candela {

namespace {
constexpr double kSmoothing = 0.3;  // weight of the newest frame in the cost estimate
}

InteractivePolicy::InteractivePolicy(double frameBudgetSeconds, double settleSeconds)
    : budget_(frameBudgetSeconds), settle_(settleSeconds) {}

uint32_t InteractivePolicy::divisorFor(uint32_t width, uint32_t height) const {
  const double fullFrame = secondsPerSample_ * double(width) * double(height);
  if (fullFrame <= budget_) return 1;
  // Dividing both sides by d divides the work by d^2.
  const double d = std::ceil(std::sqrt(fullFrame / budget_));
  return uint32_t(std::min(d, double(kMaxDivisor)));
}

FramePlan InteractivePolicy::plan(uint32_t fullWidth, uint32_t fullHeight, uint32_t samplesPerFrame, bool cameraMoved,
                                  double now) {
  if (cameraMoved) lastMotion_ = now;
  const bool preview = now - lastMotion_ < settle_;
  if (preview && !inPreview_) divisor_ = divisorFor(fullWidth, fullHeight);
  inPreview_ = preview;

  FramePlan plan;
  plan.preview = preview;
  if (!preview) {
    plan.width = fullWidth;
    plan.height = fullHeight;
    plan.samplesPerPixel = samplesPerFrame;
    return plan;
  }
  plan.width = std::max(1u, fullWidth / divisor_);
  plan.height = std::max(1u, fullHeight / divisor_);
  plan.samplesPerPixel = 1;
  return plan;
}

void InteractivePolicy::recordFrame(const FramePlan& plan, double seconds) {
  const double samples = double(plan.width) * double(plan.height) * double(plan.samplesPerPixel);
  if (samples <= 0.0 || !(seconds >= 0.0)) return;
  const double perSample = seconds / samples;
  secondsPerSample_ =
      secondsPerSample_ == 0.0 ? perSample : (1.0 - kSmoothing) * secondsPerSample_ + kSmoothing * perSample;
}

}  // namespace candela
