#include "backends/optix/module_compilation.h"

#include <optix.h>
#include <optix_stubs.h>

#include <cstring>
#include <string>
#include <vector>

#include "backends/optix/optix_error.h"
#include "backends/optix/optix_log.h"

namespace candela::optix {

ModuleCompilation::ModuleCompilation(OptixDeviceContext context, const OptixModuleCompileOptions& moduleOptions,
                                     const OptixPipelineCompileOptions& pipelineOptions, EmbeddedIr ir,
                                     tbb::task_arena& arena)
    : arena_(arena), moduleOptions_(moduleOptions), pipelineOptions_(pipelineOptions) {
  OptixTask first = nullptr;
  const OptixResult result =
      optixModuleCreateWithTasks(context, &moduleOptions_, &pipelineOptions_, reinterpret_cast<const char*>(ir.bytes),
                                 ir.size, log_.data(), &logSize_, &module_, &first);
  if (result != OPTIX_SUCCESS) {
    if (module_) optixModuleDestroy(module_);
    throwWithLog(result, "compiling the device programs", std::string(log_.data(), strnlen(log_.data(), log_.size())));
  }
  if (!first) return;
  known_ = 1;
  // Into the arena's queue, which the arena's threads serve while this one goes on (rather than spawned by a thread
  // that leaves the arena at once).
  arena_.enqueue(group_.defer([this, first] { execute(first); }));
}

ModuleCompilation::~ModuleCompilation() {
  try {
    waitForTasks();
  } catch (...) {  // a task's std::bad_alloc: the tasks have ended all the same
  }
  optixModuleDestroy(module_);
}

void ModuleCompilation::run(OptixTask task) {
  group_.run([this, task] { execute(task); });
}

void ModuleCompilation::execute(OptixTask task) {
  std::vector<OptixTask> more(size_t(tbb::this_task_arena::max_concurrency()));
  unsigned int created = 0;
  const OptixResult result = optixTaskExecute(task, more.data(), unsigned(more.size()), &created);
  int none = OPTIX_SUCCESS;
  if (result != OPTIX_SUCCESS) firstFailure_.compare_exchange_strong(none, result);
  known_ += created;
  for (unsigned int i = 0; i < created; ++i) run(more[i]);
  ++done_;
}

void ModuleCompilation::waitForTasks() {
  arena_.execute([this] { group_.wait(); });
}

OptixModule ModuleCompilation::module() {
  waitForTasks();
  OptixModuleCompileState state = OPTIX_MODULE_COMPILE_STATE_NOT_STARTED;
  checkOptix(optixModuleGetCompilationState(module_, &state), "reading the device programs' compile state");
  if (state != OPTIX_MODULE_COMPILE_STATE_COMPLETED) {
    const int failure = firstFailure_;
    throwWithLog(failure != OPTIX_SUCCESS ? OptixResult(failure) : OPTIX_ERROR_INTERNAL_COMPILER_ERROR,
                 "compiling the device programs", std::string(log_.data(), strnlen(log_.data(), log_.size())));
  }
  return module_;
}

CompileTaskCounts ModuleCompilation::tasks() const {
  // Done first: a task adds the tasks it found to `known` before it counts itself done.
  const uint32_t done = done_;
  return {done, known_};
}

}  // namespace candela::optix
