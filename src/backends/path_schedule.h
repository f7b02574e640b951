#pragma once
// How the GPU backend organises a sample's launches (backends/optix/wavefront_schedule.h): one thread follows its
// path from ray to ray (the megakernel), or each bounce is a few launches over queues of paths (the wavefront).
// Which is faster depends on the scene (docs/performance.md): the wavefront where paths run several bounces, the
// megakernel where most of them end at their first hit or miss, whose queues cost the wavefront more than their
// work. Both compute the same samples, up to the rounding of fused multiply-adds.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace candela {

enum class PathSchedule { Auto, Megakernel, Wavefront };

// "auto", "megakernel", "wavefront"; nothing for any other text.
std::optional<PathSchedule> parsePathSchedule(std::string_view text);
const char* pathScheduleName(PathSchedule schedule);

// What Auto becomes, decided once per scene and settings from the rays a probe sample traces per pixel: the
// wavefront from kWavefrontRaysPerSample on. The probe is a deterministic sample, so the same scene and settings
// always get the same schedule, and renders stay reproducible (a resumed render equals an uninterrupted one).
class PathScheduleChoice {
 public:
  // Between the bench scenes' rays per sample where the megakernel is faster (DamagedHelmet under an HDR map, about
  // one ray a sample) and those where the wavefront is (the Cornell scenes and the cut-outs, about three):
  // docs/performance.md, 'GPU frame times'.
  static constexpr double kWavefrontRaysPerSample = 2.0;

  explicit PathScheduleChoice(PathSchedule requested = PathSchedule::Auto) : requested_(requested) {}

  void request(PathSchedule schedule);
  PathSchedule requested() const { return requested_; }
  // Forgets Auto's decision (and that the wavefront did not fit), for a new scene or new settings.
  void reset() {
    decided_.reset();
    wavefrontUnavailable_ = false;
  }

  // Whether the next launch can go ahead (else the probe is due), and with which schedule (never Auto).
  bool decided() const { return requested_ != PathSchedule::Auto || decided_.has_value(); }
  PathSchedule next() const;
  // Auto's decision from the probe's rays per sample (camera, bounce and shadow rays over pixels).
  void decide(double raysPerSample);
  // The wavefront cannot run (its paths and queues do not fit in device memory): the megakernel renders.
  void wavefrontUnavailable();

  // One line for the log: the schedule and why.
  std::string describe() const;

  // Equal choices describe themselves alike.
  bool operator==(const PathScheduleChoice&) const = default;

 private:
  PathSchedule requested_;
  std::optional<PathSchedule> decided_;
  double raysPerSample_ = 0.0;
  bool wavefrontUnavailable_ = false;
};

}  // namespace candela
