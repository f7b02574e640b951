#pragma once
// Which of the GPU backend's pipelines, and so which of its modules, its next frame needs, and which it will likely
// need soon, from what it renders: those modules are what the backend compiles (program_modules.h), the needed ones
// at once, the likely ones in the background. Free of OptiX types, so that it is tested without a GPU.
#include <cstddef>
#include <vector>

#include "backends/path_schedule.h"
#include "scene/flat_scene.h"

namespace candela::optix {

// The modules of the device programs: each .cu file of device/ is one (program_modules.h), and the path tracers'
// are also compiled as the lean kernel (kernel/kernel_variant.h). A new module is an entry here and its OptiX-IR's
// in program_modules.cpp (moduleIr).
enum class ProgramModule {
  Rays,           // closest-hit, any-hit and miss programs, which every pipeline holds (device/ray_programs.cu)
  Megakernel,     // device/megakernel_programs.cu
  AovMegakernel,  // device/aov_megakernel_programs.cu
  Wavefront,      // device/wavefront_programs.cu
  RawTrace,       // device/raw_trace_programs.cu
  Restir,         // device/restir_programs.cu
  Media,          // device/media_programs.cu
  LeanMegakernel,
  LeanAovMegakernel,
  LeanWavefront,
};
constexpr size_t kProgramModuleCount = size_t(ProgramModule::LeanWavefront) + 1;

enum class RaygenProgram {
  Render,
  Record,
  // The record program's copy in the AOV path tracer's module: it only shapes that pipeline (program_use.cpp).
  RecordBesideAovs,
  RawTrace,
  RenderWithAovs,
  // The wavefront schedule's (backends/optix/wavefront_schedule.h)
  PathTrace,
  PathShade,
  PathTail,
  PathFinish,
  // ReSTIR DI's four launches per sample (kernel/restir/restir_passes.h)
  RestirPrimary,
  RestirPresample,
  RestirCandidates,
  RestirShade,
  RestirShadeWithAovs,
  // The megakernel of scenes with participating media, without and with the AOVs
  RenderMedia,
  RenderMediaWithAovs,
};

// Which raygen programs share a pipeline (program_use.cpp says why they are grouped so). ReSTIR's launches, the
// AOV path tracer, the raw trace and the path tracer of scenes with participating media (with and without AOVs)
// each have a pipeline of their own.
enum class PipelineKind { Megakernel, RawTrace, AovMegakernel, Wavefront, Restir, Media };
constexpr size_t kPipelineKinds = 6;

const std::vector<RaygenProgram>& pipelinePrograms(PipelineKind kind);
// The pipeline that launches `program`.
PipelineKind pipelineLaunching(RaygenProgram program);
// `lean`: the scene needs only the lean kernel (leanKernelSuffices), whose module then holds the path tracers.
ProgramModule moduleHolding(RaygenProgram program, bool lean);
// The modules the pipelines of `kinds` are made of: the ray programs' and each raygen program's, once.
std::vector<ProgramModule> modulesOf(const std::vector<PipelineKind>& kinds, bool lean);

// Whether the lean kernel renders `scene` as the full kernel does (kernel/kernel_variant.h): no material of a model
// it leaves out, no thin film and no curves. Its path tracers compile in less time on a first start.
bool leanKernelSuffices(const FlatScene& scene);

// What the next frames render.
struct ProgramUse {
  // The schedule of renders without AOVs: the one requested, or the one Auto decided; Auto while it has not
  // decided (its probe runs on the megakernel, and it picks the wavefront for most scenes).
  PathSchedule schedule = PathSchedule::Auto;
  bool aovs = false;
  bool restir = false;
  bool media = false;  // the scene has participating media: their megakernel renders, whatever the schedule
  // The schedule is Auto's (undecided, or its decision) rather than requested: the megakernel may then render in
  // the wavefront's place while the wavefront's programs compile, since both draw the same samples
  // (backends/path_schedule.h).
  bool megakernelMayStandIn = true;
};

// The pipelines the next frames launch, whose modules compile at once.
std::vector<PipelineKind> pipelinesNeeded(const ProgramUse& use);
// The pipelines the next frame waits for: those it needs, but the megakernel's alone where it may stand in for the
// wavefront. On a first start its module compiles in about half the wavefront's time (docs/performance.md,
// 'The first start'), so the first image comes that much sooner, and the wavefront takes over once compiled.
std::vector<PipelineKind> pipelinesAwaited(const ProgramUse& use);
// The pipelines an interactive session will likely switch to: the AOV path tracer, which each denoiser and the
// bilateral filter turn on, and back from it the plain path tracer. Never ReSTIR's, which is chosen at start.
std::vector<PipelineKind> pipelinesLikely(const ProgramUse& use);

}  // namespace candela::optix
