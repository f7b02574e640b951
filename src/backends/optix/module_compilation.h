#pragma once
// One OptiX module compiled from OptiX-IR in the background: optixModuleCreateWithTasks splits the compile into
// tasks, which run on TBB's threads in the task arena given while the thread that started it goes on; each task
// may find more (optixTaskExecute), which run there too. NVIDIA's optixCompileWithTasks sample does the same on a
// thread pool of its own.
#include <optix_types.h>
#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include <array>
#include <atomic>
#include <cstddef>

#include "backends/optix/compile_progress.h"

namespace candela::optix {

// OptiX-IR that the build embedded in the binary (CMakeLists.txt).
struct EmbeddedIr {
  const unsigned char* bytes;
  size_t size;
};

class ModuleCompilation {
 public:
  // Starts the compile with options that must be those of every module of a pipeline. Throws OptixError with
  // OptiX's log when it cannot start.
  ModuleCompilation(OptixDeviceContext context, const OptixModuleCompileOptions& moduleOptions,
                    const OptixPipelineCompileOptions& pipelineOptions, EmbeddedIr ir, tbb::task_arena& arena);
  // Waits for the compile to finish: OptiX destroys no module while its tasks run, and a finished module is in
  // OptiX's disk cache, so that the next start need not compile it.
  ~ModuleCompilation();
  ModuleCompilation(const ModuleCompilation&) = delete;
  ModuleCompilation& operator=(const ModuleCompilation&) = delete;

  // The module, once compiled: waits for the compile, taking part in its tasks. Throws OptixError with OptiX's log
  // when it failed (optixModuleGetCompilationState).
  OptixModule module();
  // The compile has ended (module() does not wait) once every task known is done.
  CompileTaskCounts tasks() const;

 private:
  void run(OptixTask task);  // from a task: into the running thread's pool, in the arena
  void execute(OptixTask task);
  void waitForTasks();

  tbb::task_arena& arena_;
  tbb::task_group group_;
  // OptiX reads these while the tasks run, and writes the log.
  OptixModuleCompileOptions moduleOptions_;
  OptixPipelineCompileOptions pipelineOptions_;
  std::array<char, 8192> log_{};
  size_t logSize_ = sizeof log_;
  OptixModule module_ = nullptr;
  std::atomic<uint32_t> done_{0}, known_{0};
  std::atomic<int> firstFailure_{OPTIX_SUCCESS};  // the first task's error, an OptixResult
};

}  // namespace candela::optix
