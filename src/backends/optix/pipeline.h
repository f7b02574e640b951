#pragma once
// The OptiX module built from the embedded OptiX-IR, and pipelines that each hold some of its raygen programs
// with a shader binding table for each. OptiX compiles and sizes every pipeline on its own, so the raw-trace
// ceiling can be kept apart from the path tracer's shading code.
#include <optix_types.h>

#include <vector>

#include "backends/optix/device_buffer.h"

namespace candela::optix {

enum class RaygenProgram {
  Render,
  Record,
  RawTrace,
  RenderWithAovs,
  // The wavefront schedule's (backends/optix/wavefront_schedule.h)
  PathTrace,
  PathShade,
  PathTail,
  PathFinish,
};

// Options every pipeline over the module must be created with.
OptixPipelineCompileOptions pipelineCompileOptions();

class ProgramModule {
 public:
  explicit ProgramModule(OptixDeviceContext context);
  ~ProgramModule();
  ProgramModule(const ProgramModule&) = delete;
  ProgramModule& operator=(const ProgramModule&) = delete;
  OptixModule get() const { return module_; }

 private:
  OptixModule module_ = nullptr;
};

// A pipeline holding some of the raygen programs, with one shader binding table for each; the tables share
// the miss and hit-group records.
class Pipeline {
 public:
  Pipeline(OptixDeviceContext context, OptixModule module, const std::vector<RaygenProgram>& programs);
  ~Pipeline();
  Pipeline(const Pipeline&) = delete;
  Pipeline& operator=(const Pipeline&) = delete;

  OptixPipeline get() const { return pipeline_; }
  bool has(RaygenProgram program) const;
  const OptixShaderBindingTable& bindingTable(RaygenProgram program) const;

 private:
  std::vector<RaygenProgram> programs_;
  std::vector<OptixProgramGroup> groups_;  // the raygen programs in order, then radiance/shadow miss and hit
  OptixPipeline pipeline_ = nullptr;
  DeviceBuffer records_;
  std::vector<OptixShaderBindingTable> tables_;  // one per raygen program
};

}  // namespace candela::optix
