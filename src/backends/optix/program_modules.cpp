#include "backends/optix/program_modules.h"

// The device programs as OptiX-IR, embedded at build time (CMakeLists.txt).
extern const unsigned char candelaRayPrograms[], candelaMegakernelPrograms[], candelaAovMegakernelPrograms[],
    candelaWavefrontPrograms[], candelaRawTracePrograms[], candelaRestirPrograms[];
extern const size_t candelaRayProgramsSize, candelaMegakernelProgramsSize, candelaAovMegakernelProgramsSize,
    candelaWavefrontProgramsSize, candelaRawTraceProgramsSize, candelaRestirProgramsSize;

namespace candela::optix {

namespace {

EmbeddedIr moduleIr(ProgramModule module) {
  switch (module) {
    case ProgramModule::Rays: return {candelaRayPrograms, candelaRayProgramsSize};
    case ProgramModule::Megakernel: return {candelaMegakernelPrograms, candelaMegakernelProgramsSize};
    case ProgramModule::AovMegakernel: return {candelaAovMegakernelPrograms, candelaAovMegakernelProgramsSize};
    case ProgramModule::Wavefront: return {candelaWavefrontPrograms, candelaWavefrontProgramsSize};
    case ProgramModule::RawTrace: return {candelaRawTracePrograms, candelaRawTraceProgramsSize};
    case ProgramModule::Restir: return {candelaRestirPrograms, candelaRestirProgramsSize};
  }
  return {nullptr, 0};
}

OptixModuleCompileOptions moduleCompileOptions() {
  OptixModuleCompileOptions options{};
  options.optLevel = OPTIX_COMPILE_OPTIMIZATION_DEFAULT;
  options.debugLevel = OPTIX_COMPILE_DEBUG_LEVEL_MINIMAL;
  return options;
}

}  // namespace

OptixPipelineCompileOptions pipelineCompileOptions() {
  OptixPipelineCompileOptions options{};
  options.usesMotionBlur = 0;
  options.traversableGraphFlags = OPTIX_TRAVERSABLE_GRAPH_FLAG_ALLOW_SINGLE_LEVEL_INSTANCING;
  // Radiance: random bits in, then t, b1, b2, instance, primitive out; shadow: random bits, occluded.
  options.numPayloadValues = 5;
  options.numAttributeValues = 2;  // built-in triangle barycentrics
  options.exceptionFlags = OPTIX_EXCEPTION_FLAG_NONE;
  options.pipelineLaunchParamsVariableName = "params";
  options.usesPrimitiveTypeFlags = OPTIX_PRIMITIVE_TYPE_FLAGS_TRIANGLE;
  return options;
}

ProgramModules::ProgramModules(OptixDeviceContext context, const std::vector<ProgramModule>& first) {
  const OptixModuleCompileOptions moduleOptions = moduleCompileOptions();
  const OptixPipelineCompileOptions pipelineOptions = pipelineCompileOptions();
  auto start = [&](ProgramModule module, tbb::task_arena& arena) {
    modules_[size_t(module)] =
        std::make_unique<ModuleCompilation>(context, moduleOptions, pipelineOptions, moduleIr(module), arena);
  };
  for (ProgramModule module : first) start(module, first_);
  for (size_t m = 0; m < kProgramModuleCount; ++m)
    if (!modules_[m]) start(ProgramModule(m), rest_);
}

OptixModule ProgramModules::get(ProgramModule module) { return modules_[size_t(module)]->module(); }

CompileTaskCounts ProgramModules::tasks(const std::vector<ProgramModule>& modules) const {
  CompileTaskCounts sum;
  for (ProgramModule module : modules) {
    const CompileTaskCounts counts = modules_[size_t(module)]->tasks();
    sum.done += counts.done;
    sum.known += counts.known;
  }
  return sum;
}

}  // namespace candela::optix
