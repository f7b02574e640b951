#pragma once
// Which of the GPU backend's pipelines its next frame needs, and which it will likely need soon, from what it
// renders: their modules are what the backend compiles (program_modules.h), the needed ones at once, the likely
// ones in the background. Free of OptiX types, so that it is tested without a GPU.
#include <cstddef>
#include <vector>

#include "backends/path_schedule.h"

namespace candela::optix {

// Which raygen programs share a pipeline (optix_backend.cpp says why they are grouped so). ReSTIR's launches, the
// AOV path tracer, the raw trace and the path tracer of scenes with participating media (with and without AOVs)
// each have a pipeline of their own.
enum class PipelineKind { Megakernel, RawTrace, AovMegakernel, Wavefront, Restir, Media };
constexpr size_t kPipelineKinds = 6;

// What the next frames render.
struct ProgramUse {
  // The schedule of renders without AOVs: the one requested, or the one Auto decided; Auto while it has not
  // decided (its probe runs on the megakernel, and it picks the wavefront for most scenes).
  PathSchedule schedule = PathSchedule::Auto;
  bool aovs = false;
  bool restir = false;
  bool media = false;  // the scene has participating media: their megakernel renders, whatever the schedule
};

// The pipelines the next frame launches.
std::vector<PipelineKind> pipelinesNeeded(const ProgramUse& use);
// The pipelines an interactive session will likely switch to: the AOV path tracer, which each denoiser and the
// bilateral filter turn on, and back from it the plain path tracer. Never ReSTIR's, which is chosen at start.
std::vector<PipelineKind> pipelinesLikely(const ProgramUse& use);

}  // namespace candela::optix
