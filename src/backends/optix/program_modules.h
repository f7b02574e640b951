#pragma once
// The device programs' OptiX modules: each .cu file of device/ is compiled to OptiX-IR at build time, embedded in
// the binary, and compiled for the GPU here, in the background, only once something asks for it (ModuleCompilation).
// Each pipeline's raygen programs are modules of their own (pipeline.h says which), so that a frame waits only for
// the modules of its pipelines, and a run compiles only the modules of what it renders: a first start on a
// machine, whose OptiX disk cache is empty, need not compile ReSTIR's programs to show a frame without it.
#include <optix_types.h>
#include <tbb/task_arena.h>

#include <array>
#include <chrono>
#include <memory>
#include <vector>

#include "backends/optix/compile_progress.h"
#include "backends/optix/module_compilation.h"
#include "backends/optix/program_use.h"

namespace candela::optix {

// Options every module and every pipeline over them must be created with.
OptixPipelineCompileOptions pipelineCompileOptions();

// How a compile shares the processor's threads.
enum class CompilePriority {
  Needed,    // a frame waits for it
  Prefetch,  // likely needed later: it takes only the threads the needed compiles leave
};

class ProgramModules {
 public:
  // Compiles nothing yet.
  explicit ProgramModules(OptixDeviceContext context);

  // Begins compiling `module` in the background, unless it has begun. A begun compile keeps its priority: OptiX's
  // tasks cannot move to another arena (nor be cancelled), though a thread that waits for them (get) takes part.
  void start(ProgramModule module, CompilePriority priority);
  // The compiled module: starts its compile where it has not begun, and waits for it, taking part. Throws
  // OptixError with OptiX's log when it failed.
  OptixModule get(ProgramModule module);

  bool started(ProgramModule module) const;
  // Whether every one of `modules` has begun and ended (compiled or failed): get() then does not wait.
  bool finished(const std::vector<ProgramModule>& modules) const;
  std::vector<ProgramModule> startedModules() const;
  // The built-in intersection program of round cubic Bezier curves (kernel/curve.h), for the curves' hit groups
  // (OptiX owns it: it is never destroyed).
  OptixModule curveIntersection();
  // The tasks of the modules' compiles, summed (none for a module not begun).
  CompileTaskCounts tasks(const std::vector<ProgramModule>& modules) const;
  // Since the first of the modules began compiling; 0 where none has.
  double secondsCompiling(const std::vector<ProgramModule>& modules) const;

 private:
  using Clock = std::chrono::steady_clock;

  OptixDeviceContext context_;
  tbb::task_arena needed_;
  tbb::task_arena prefetch_{tbb::task_arena::automatic, 1, tbb::task_arena::priority::low};
  std::array<Clock::time_point, kProgramModuleCount> startedAt_{};
  std::array<std::unique_ptr<ModuleCompilation>, kProgramModuleCount> modules_;  // ended before the arenas
  OptixModule curveIntersection_ = nullptr;
};

}  // namespace candela::optix
