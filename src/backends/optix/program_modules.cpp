#include "backends/optix/program_modules.h"

#include <optix.h>
#include <optix_stubs.h>

#include <optional>

#include "backends/optix/acceleration.h"
#include "backends/optix/optix_error.h"

// The device programs as OptiX-IR, embedded at build time (CMakeLists.txt).
extern const unsigned char candelaRayPrograms[], candelaMegakernelPrograms[], candelaAovMegakernelPrograms[],
    candelaWavefrontPrograms[], candelaRawTracePrograms[], candelaRestirPrograms[], candelaMediaPrograms[],
    candelaLeanMegakernelPrograms[], candelaLeanAovMegakernelPrograms[], candelaLeanWavefrontPrograms[];
extern const size_t candelaRayProgramsSize, candelaMegakernelProgramsSize, candelaAovMegakernelProgramsSize,
    candelaWavefrontProgramsSize, candelaRawTraceProgramsSize, candelaRestirProgramsSize, candelaMediaProgramsSize,
    candelaLeanMegakernelProgramsSize, candelaLeanAovMegakernelProgramsSize, candelaLeanWavefrontProgramsSize;

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
    case ProgramModule::Media: return {candelaMediaPrograms, candelaMediaProgramsSize};
    case ProgramModule::LeanMegakernel: return {candelaLeanMegakernelPrograms, candelaLeanMegakernelProgramsSize};
    case ProgramModule::LeanAovMegakernel:
      return {candelaLeanAovMegakernelPrograms, candelaLeanAovMegakernelProgramsSize};
    case ProgramModule::LeanWavefront: return {candelaLeanWavefrontPrograms, candelaLeanWavefrontProgramsSize};
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
  options.numAttributeValues = 2;  // built-in triangle barycentrics; a curve's u takes one
  options.exceptionFlags = OPTIX_EXCEPTION_FLAG_NONE;
  options.pipelineLaunchParamsVariableName = "params";
  options.usesPrimitiveTypeFlags = OPTIX_PRIMITIVE_TYPE_FLAGS_TRIANGLE | OPTIX_PRIMITIVE_TYPE_FLAGS_ROUND_CUBIC_BEZIER;
  return options;
}

ProgramModules::ProgramModules(OptixDeviceContext context) : context_(context) {}

void ProgramModules::start(ProgramModule module, CompilePriority priority) {
  std::unique_ptr<ModuleCompilation>& compilation = modules_[size_t(module)];
  if (compilation) return;
  startedAt_[size_t(module)] = Clock::now();
  compilation =
      std::make_unique<ModuleCompilation>(context_, moduleCompileOptions(), pipelineCompileOptions(), moduleIr(module),
                                          priority == CompilePriority::Needed ? needed_ : prefetch_);
}

OptixModule ProgramModules::get(ProgramModule module) {
  start(module, CompilePriority::Needed);
  return modules_[size_t(module)]->module();
}

OptixModule ProgramModules::curveIntersection() {
  if (curveIntersection_) return curveIntersection_;
  OptixBuiltinISOptions options{};
  options.builtinISModuleType = OPTIX_PRIMITIVE_TYPE_ROUND_CUBIC_BEZIER;
  options.usesMotionBlur = 0;
  options.buildFlags = kMeshBuildFlags;
  options.curveEndcapFlags = OPTIX_CURVE_ENDCAP_DEFAULT;
  const OptixModuleCompileOptions moduleOptions = moduleCompileOptions();
  const OptixPipelineCompileOptions pipelineOptions = pipelineCompileOptions();
  checkOptix(optixBuiltinISModuleGet(context_, &moduleOptions, &pipelineOptions, &options, &curveIntersection_),
             "getting the curves' intersection program");
  return curveIntersection_;
}

bool ProgramModules::started(ProgramModule module) const { return modules_[size_t(module)] != nullptr; }

bool ProgramModules::finished(const std::vector<ProgramModule>& modules) const {
  for (ProgramModule module : modules) {
    if (!started(module)) return false;
    const CompileTaskCounts counts = modules_[size_t(module)]->tasks();
    if (counts.done != counts.known) return false;
  }
  return true;
}

std::vector<ProgramModule> ProgramModules::startedModules() const {
  std::vector<ProgramModule> begun;
  for (size_t m = 0; m < kProgramModuleCount; ++m)
    if (modules_[m]) begun.push_back(ProgramModule(m));
  return begun;
}

CompileTaskCounts ProgramModules::tasks(const std::vector<ProgramModule>& modules) const {
  CompileTaskCounts sum;
  for (ProgramModule module : modules) {
    if (!started(module)) continue;
    const CompileTaskCounts counts = modules_[size_t(module)]->tasks();
    sum.done += counts.done;
    sum.known += counts.known;
  }
  return sum;
}

double ProgramModules::secondsCompiling(const std::vector<ProgramModule>& modules) const {
  std::optional<Clock::time_point> first;
  for (ProgramModule module : modules)
    if (started(module) && (!first || startedAt_[size_t(module)] < *first)) first = startedAt_[size_t(module)];
  return first ? std::chrono::duration<double>(Clock::now() - *first).count() : 0.0;
}

}  // namespace candela::optix
