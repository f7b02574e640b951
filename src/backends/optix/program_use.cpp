#include "backends/optix/program_use.h"

#include <algorithm>
#include <array>
#include <stdexcept>

#include "kernel/bsdf/material_models.h"

namespace candela::optix {

// Which raygen programs share a pipeline: the path tracer runs much faster beside the record program than alone
// or beside the raw-trace program (docs/performance-log.md, 'GPU (OptiX)'). OptiX decides per pipeline how to
// compile traversal around each trace call, and does not document it, so this grouping is what the measurement
// chose. The AOV path tracer gets a pipeline of its own, shaped like the path tracer's (beside a copy of the record
// program, compiled in its own module so that a render with AOVs does not compile the path tracer's module too),
// so that it leaves the path tracer's alone. ReSTIR's launches have a pipeline of their own, and so has the megakernel
// of scenes with participating media.
const std::vector<RaygenProgram>& pipelinePrograms(PipelineKind kind) {
  static const std::array<std::vector<RaygenProgram>, kPipelineKinds> programs = {{
      {RaygenProgram::Render, RaygenProgram::Record},
      {RaygenProgram::RawTrace},
      {RaygenProgram::RenderWithAovs, RaygenProgram::RecordBesideAovs},
      {RaygenProgram::PathTrace, RaygenProgram::PathShade, RaygenProgram::PathTail, RaygenProgram::PathFinish},
      {RaygenProgram::RestirPrimary, RaygenProgram::RestirPresample, RaygenProgram::RestirCandidates,
       RaygenProgram::RestirShade, RaygenProgram::RestirShadeWithAovs},
      {RaygenProgram::RenderMedia, RaygenProgram::RenderMediaWithAovs},
  }};
  return programs[size_t(kind)];
}

PipelineKind pipelineLaunching(RaygenProgram program) {
  switch (program) {
    case RaygenProgram::Render:
    case RaygenProgram::Record: return PipelineKind::Megakernel;
    case RaygenProgram::RawTrace: return PipelineKind::RawTrace;
    case RaygenProgram::RenderWithAovs:
    case RaygenProgram::RecordBesideAovs: return PipelineKind::AovMegakernel;
    case RaygenProgram::PathTrace:
    case RaygenProgram::PathShade:
    case RaygenProgram::PathTail:
    case RaygenProgram::PathFinish: return PipelineKind::Wavefront;
    case RaygenProgram::RestirPrimary:
    case RaygenProgram::RestirPresample:
    case RaygenProgram::RestirCandidates:
    case RaygenProgram::RestirShade:
    case RaygenProgram::RestirShadeWithAovs: return PipelineKind::Restir;
    case RaygenProgram::RenderMedia:
    case RaygenProgram::RenderMediaWithAovs: return PipelineKind::Media;
  }
  throw std::logic_error("no pipeline launches the raygen program");
}

ProgramModule moduleHolding(RaygenProgram program, bool lean) {
  switch (program) {
    case RaygenProgram::Render:
    case RaygenProgram::Record: return lean ? ProgramModule::LeanMegakernel : ProgramModule::Megakernel;
    case RaygenProgram::RawTrace: return ProgramModule::RawTrace;
    case RaygenProgram::RenderWithAovs:
    case RaygenProgram::RecordBesideAovs: return lean ? ProgramModule::LeanAovMegakernel : ProgramModule::AovMegakernel;
    case RaygenProgram::PathTrace:
    case RaygenProgram::PathShade:
    case RaygenProgram::PathTail:
    case RaygenProgram::PathFinish: return lean ? ProgramModule::LeanWavefront : ProgramModule::Wavefront;
    case RaygenProgram::RestirPrimary:
    case RaygenProgram::RestirPresample:
    case RaygenProgram::RestirCandidates:
    case RaygenProgram::RestirShade:
    case RaygenProgram::RestirShadeWithAovs: return ProgramModule::Restir;
    case RaygenProgram::RenderMedia:
    case RaygenProgram::RenderMediaWithAovs: return ProgramModule::Media;
  }
  throw std::logic_error("no module holds the raygen program");
}

std::vector<ProgramModule> modulesOf(const std::vector<PipelineKind>& kinds, bool lean) {
  std::vector<ProgramModule> modules{ProgramModule::Rays};
  for (PipelineKind kind : kinds)
    for (RaygenProgram program : pipelinePrograms(kind))
      if (std::find(modules.begin(), modules.end(), moduleHolding(program, lean)) == modules.end())
        modules.push_back(moduleHolding(program, lean));
  return modules;
}

bool leanKernelSuffices(const FlatScene& scene) {
  if (!scene.curveSegments.empty()) return false;
  return std::all_of(scene.materials.begin(), scene.materials.end(),
                     [](const Material& m) { return leanKernelRenders(m); });
}

std::vector<PipelineKind> pipelinesNeeded(const ProgramUse& use) {
  if (use.media) return {PipelineKind::Media};    // with or without AOVs
  if (use.restir) return {PipelineKind::Restir};  // with or without AOVs
  if (use.aovs) return {PipelineKind::AovMegakernel};
  switch (use.schedule) {
    case PathSchedule::Megakernel: return {PipelineKind::Megakernel};
    case PathSchedule::Wavefront: return {PipelineKind::Wavefront};
    case PathSchedule::Auto: break;
  }
  return {PipelineKind::Megakernel, PipelineKind::Wavefront};
}

std::vector<PipelineKind> pipelinesAwaited(const ProgramUse& use) {
  if (!use.media && !use.restir && !use.aovs && use.megakernelMayStandIn) return {PipelineKind::Megakernel};
  return pipelinesNeeded(use);
}

std::vector<PipelineKind> pipelinesLikely(const ProgramUse& use) {
  if (use.restir || use.media) return {};
  if (use.aovs) return pipelinesNeeded({use.schedule, false, false});
  return {PipelineKind::AovMegakernel};
}

}  // namespace candela::optix
