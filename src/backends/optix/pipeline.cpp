#include "backends/optix/pipeline.h"

#include <optix.h>
#include <optix_stack_size.h>
#include <optix_stubs.h>

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "backends/optix/launch_params.h"
#include "backends/optix/optix_error.h"
#include "backends/optix/optix_log.h"

namespace candela::optix {

namespace {

const char* raygenName(RaygenProgram program) {
  switch (program) {
    case RaygenProgram::Render: return "__raygen__render";
    case RaygenProgram::Record:
    case RaygenProgram::RecordBesideAovs: return "__raygen__record";
    case RaygenProgram::RawTrace: return "__raygen__rawTrace";
    case RaygenProgram::RenderWithAovs: return "__raygen__renderWithAovs";
    case RaygenProgram::PathTrace: return "__raygen__pathTrace";
    case RaygenProgram::PathShade: return "__raygen__pathShade";
    case RaygenProgram::PathTail: return "__raygen__pathTail";
    case RaygenProgram::PathFinish: return "__raygen__pathFinish";
    case RaygenProgram::RestirPrimary: return "__raygen__restirPrimary";
    case RaygenProgram::RestirPresample: return "__raygen__restirPresample";
    case RaygenProgram::RestirCandidates: return "__raygen__restirCandidates";
    case RaygenProgram::RestirShade: return "__raygen__restirShade";
    case RaygenProgram::RestirShadeWithAovs: return "__raygen__restirShadeWithAovs";
    case RaygenProgram::RenderMedia: return "__raygen__renderMedia";
    case RaygenProgram::RenderMediaWithAovs: return "__raygen__renderMediaWithAovs";
  }
  throw std::logic_error("no such raygen program");
}

struct alignas(OPTIX_SBT_RECORD_ALIGNMENT) HeaderOnlyRecord {
  char header[OPTIX_SBT_RECORD_HEADER_SIZE];
};

}  // namespace

Pipeline::Pipeline(OptixDeviceContext context, ProgramModules& modules, const std::vector<RaygenProgram>& programs,
                   bool lean)
    : programs_(programs) {
  const OptixModule rays = modules.get(ProgramModule::Rays);
  const size_t raygens = programs.size();
  const size_t radianceMiss = raygens, shadowMiss = raygens + 1, radianceHit = raygens + 2, shadowHit = raygens + 3;
  const size_t curveRadianceHit = raygens + 4, curveShadowHit = raygens + 5;
  std::vector<OptixProgramGroupDesc> descriptions(raygens + 6);
  for (size_t i = 0; i < raygens; ++i) {
    descriptions[i].kind = OPTIX_PROGRAM_GROUP_KIND_RAYGEN;
    descriptions[i].raygen.module = modules.get(moduleHolding(programs[i], lean));
    descriptions[i].raygen.entryFunctionName = raygenName(programs[i]);
  }
  // The radiance miss program would only restate the payload's "missed" sentinel, so it is absent.
  descriptions[radianceMiss].kind = OPTIX_PROGRAM_GROUP_KIND_MISS;
  descriptions[shadowMiss].kind = OPTIX_PROGRAM_GROUP_KIND_MISS;
  descriptions[shadowMiss].miss.module = rays;
  descriptions[shadowMiss].miss.entryFunctionName = "__miss__shadow";
  // Both hit groups hold the pass-through any-hit program; triangles whose material does not use alpha are
  // built with any-hit disabled (acceleration.cpp), so only those that do run it. Shadow rays disable
  // closest-hit.
  descriptions[radianceHit].kind = OPTIX_PROGRAM_GROUP_KIND_HITGROUP;
  descriptions[radianceHit].hitgroup.moduleCH = rays;
  descriptions[radianceHit].hitgroup.entryFunctionNameCH = "__closesthit__radiance";
  descriptions[radianceHit].hitgroup.moduleAH = rays;
  descriptions[radianceHit].hitgroup.entryFunctionNameAH = "__anyhit__passThrough";
  descriptions[shadowHit].kind = OPTIX_PROGRAM_GROUP_KIND_HITGROUP;
  descriptions[shadowHit].hitgroup.moduleAH = rays;
  descriptions[shadowHit].hitgroup.entryFunctionNameAH = "__anyhit__passThrough";
  // Curves: OptiX's built-in intersection program, and an any-hit program that passes the tubes' inner walls
  // (their materials' alpha is not applied).
  const OptixModule curves = modules.curveIntersection();
  descriptions[curveRadianceHit].kind = OPTIX_PROGRAM_GROUP_KIND_HITGROUP;
  descriptions[curveRadianceHit].hitgroup.moduleIS = curves;
  descriptions[curveRadianceHit].hitgroup.moduleCH = rays;
  descriptions[curveRadianceHit].hitgroup.entryFunctionNameCH = "__closesthit__curve";
  descriptions[curveRadianceHit].hitgroup.moduleAH = rays;
  descriptions[curveRadianceHit].hitgroup.entryFunctionNameAH = "__anyhit__curveRadiance";
  descriptions[curveShadowHit].kind = OPTIX_PROGRAM_GROUP_KIND_HITGROUP;
  descriptions[curveShadowHit].hitgroup.moduleIS = curves;
  descriptions[curveShadowHit].hitgroup.moduleAH = rays;
  descriptions[curveShadowHit].hitgroup.entryFunctionNameAH = "__anyhit__curveShadow";
  groups_.assign(descriptions.size(), nullptr);
  OptixProgramGroupOptions groupOptions{};
  checkWithLog("creating the program groups", [&](char* log, size_t* logSize) {
    return optixProgramGroupCreate(context, descriptions.data(), unsigned(descriptions.size()), &groupOptions, log,
                                   logSize, groups_.data());
  });

  const OptixPipelineCompileOptions compileOptions = pipelineCompileOptions();
  OptixPipelineLinkOptions linkOptions{};
  linkOptions.maxTraceDepth = 1;  // only raygen traces
  checkWithLog("linking the pipeline", [&](char* log, size_t* logSize) {
    return optixPipelineCreate(context, &compileOptions, &linkOptions, groups_.data(), unsigned(groups_.size()), log,
                               logSize, &pipeline_);
  });

  OptixStackSizes stackSizes{};
  for (OptixProgramGroup group : groups_) {
#if OPTIX_VERSION >= 80000
    checkOptix(optixUtilAccumulateStackSizes(group, &stackSizes, pipeline_), "sizing the pipeline's stacks");
#else
    checkOptix(optixUtilAccumulateStackSizes(group, &stackSizes), "sizing the pipeline's stacks");
#endif
  }
  unsigned int fromTraversal = 0, fromState = 0, continuation = 0;
  checkOptix(optixUtilComputeStackSizes(&stackSizes, linkOptions.maxTraceDepth, 0, 0, &fromTraversal, &fromState,
                                        &continuation),
             "sizing the pipeline's stacks");
  checkOptix(optixPipelineSetStackSize(pipeline_, fromTraversal, fromState, continuation,
                                       /*maxTraversableGraphDepth=*/2),
             "setting the pipeline's stack size");

  // Records carry only their program headers: every program reads scene data through the launch parameters.
  // The triangles' hit-group records repeat once per SBT index a triangle can have (kHitRecordSets: a mesh's
  // cut-out classes, or a batch's build inputs), which differ only in the geometry flags the build gives them;
  // the curves' two follow (kCurveSbtOffset).
  const size_t triangleHitRecords = kHitRecordSets * kRayTypeCount;
  std::vector<HeaderOnlyRecord> records(radianceHit + triangleHitRecords + kRayTypeCount);
  for (size_t i = 0; i < curveRadianceHit; ++i)
    checkOptix(optixSbtRecordPackHeader(groups_[i], &records[i]), "packing a shader binding table record");
  for (size_t i = curveRadianceHit; i < radianceHit + triangleHitRecords; ++i) records[i] = records[i - kRayTypeCount];
  const size_t curveRecords = radianceHit + kCurveSbtOffset;
  checkOptix(optixSbtRecordPackHeader(groups_[curveRadianceHit], &records[curveRecords + kRadianceRay]),
             "packing a shader binding table record");
  checkOptix(optixSbtRecordPackHeader(groups_[curveShadowHit], &records[curveRecords + kShadowRay]),
             "packing a shader binding table record");
  records_ = DeviceBuffer::fromVector(records, "a shader binding table");
  const CUdeviceptr base = records_.address();
  tables_.resize(raygens);
  for (size_t i = 0; i < raygens; ++i) {
    OptixShaderBindingTable& table = tables_[i];
    table.raygenRecord = base + i * sizeof(HeaderOnlyRecord);
    table.missRecordBase = base + radianceMiss * sizeof(HeaderOnlyRecord);
    table.missRecordStrideInBytes = sizeof(HeaderOnlyRecord);
    table.missRecordCount = kRayTypeCount;
    table.hitgroupRecordBase = base + radianceHit * sizeof(HeaderOnlyRecord);
    table.hitgroupRecordStrideInBytes = sizeof(HeaderOnlyRecord);
    table.hitgroupRecordCount = unsigned(triangleHitRecords + kRayTypeCount);
  }
}

Pipeline::~Pipeline() {
  if (pipeline_) optixPipelineDestroy(pipeline_);
  for (OptixProgramGroup group : groups_)
    if (group) optixProgramGroupDestroy(group);
}

const OptixShaderBindingTable& Pipeline::bindingTable(RaygenProgram program) const {
  for (size_t i = 0; i < programs_.size(); ++i)
    if (programs_[i] == program) return tables_[i];
  throw std::logic_error("the raygen program is not in this pipeline");
}

}  // namespace candela::optix
