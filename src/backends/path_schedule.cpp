#include "backends/path_schedule.h"

#include <cstdio>

namespace candela {

std::optional<PathSchedule> parsePathSchedule(std::string_view text) {
  if (text == "auto") return PathSchedule::Auto;
  if (text == "megakernel") return PathSchedule::Megakernel;
  if (text == "wavefront") return PathSchedule::Wavefront;
  return std::nullopt;
}

const char* pathScheduleName(PathSchedule schedule) {
  switch (schedule) {
    case PathSchedule::Auto: return "auto";
    case PathSchedule::Megakernel: return "megakernel";
    case PathSchedule::Wavefront: return "wavefront";
  }
  return "auto";
}

void PathScheduleChoice::request(PathSchedule schedule) {
  requested_ = schedule;
  reset();
}

PathSchedule PathScheduleChoice::next() const {
  if (wavefrontUnavailable_) return PathSchedule::Megakernel;
  if (requested_ != PathSchedule::Auto) return requested_;
  return decided_.value_or(PathSchedule::Megakernel);
}

void PathScheduleChoice::decide(double raysPerSample) {
  raysPerSample_ = raysPerSample;
  decided_ = raysPerSample >= kWavefrontRaysPerSample ? PathSchedule::Wavefront : PathSchedule::Megakernel;
}

void PathScheduleChoice::wavefrontUnavailable() { wavefrontUnavailable_ = true; }

std::string PathScheduleChoice::describe() const {
  const std::string name = std::string(pathScheduleName(next())) + " schedule";
  if (wavefrontUnavailable_) return name + " (the wavefront's paths and queues do not fit in device memory)";
  if (requested_ != PathSchedule::Auto) return name + " (as requested)";
  if (!decided_) return "schedule not chosen yet";
  char why[96];
  std::snprintf(why, sizeof why, " (%.2f rays per sample, the wavefront from %.1f)", raysPerSample_,
                kWavefrontRaysPerSample);
  return name + why;
}

}  // namespace candela
