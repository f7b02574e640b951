#pragma once
// The device programs' OptiX modules: each .cu file of device/ is compiled to OptiX-IR at build time, embedded in
// the binary, and compiled for the GPU here, in the background from the start (ModuleCompilation). Each pipeline's
// raygen programs are modules of their own (pipeline.h says which), so that the pipelines a first frame needs wait
// only for theirs: those come first, in a task arena of their own; the others compile in a low-priority arena
// meanwhile, and are waited for where first used.
#include <optix_types.h>
#include <tbb/task_arena.h>

#include <array>
#include <memory>
#include <vector>

#include "backends/optix/compile_progress.h"
#include "backends/optix/module_compilation.h"

namespace candela::optix {

enum class ProgramModule {
  Rays,           // closest-hit, any-hit and miss programs, which every pipeline holds (device/ray_programs.cu)
  Megakernel,     // device/megakernel_programs.cu
  AovMegakernel,  // device/aov_megakernel_programs.cu
  Wavefront,      // device/wavefront_programs.cu
  RawTrace,       // device/raw_trace_programs.cu
  Restir,         // device/restir_programs.cu
};
constexpr size_t kProgramModuleCount = 6;

// Options every module and every pipeline over them must be created with.
OptixPipelineCompileOptions pipelineCompileOptions();

class ProgramModules {
 public:
  // Starts compiling every module, those of `first` ahead of the others.
  ProgramModules(OptixDeviceContext context, const std::vector<ProgramModule>& first);

  // The compiled module: waits for its compile, taking part. Throws OptixError with OptiX's log when it failed.
  OptixModule get(ProgramModule module);
  // The tasks of the modules' compiles, summed.
  CompileTaskCounts tasks(const std::vector<ProgramModule>& modules) const;

 private:
  tbb::task_arena first_;
  tbb::task_arena rest_{tbb::task_arena::automatic, 1, tbb::task_arena::priority::low};
  std::array<std::unique_ptr<ModuleCompilation>, kProgramModuleCount> modules_;  // ended before the arenas
};

}  // namespace candela::optix
