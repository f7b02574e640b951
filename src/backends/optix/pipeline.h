#pragma once
// The OptiX module built from the embedded OptiX-IR, and one pipeline per raygen program with its shader
// binding table. Separate pipelines keep each launch kind's kernel to its own code: OptiX sizes registers and
// stacks per pipeline, and the raw-trace ceiling must not carry the path tracer's shading code.
#include <optix_types.h>

#include "backends/optix/device_buffer.h"

namespace candela::optix {

enum class RaygenProgram { Render, Record, RawTrace };

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

class Pipeline {
 public:
  Pipeline(OptixDeviceContext context, OptixModule module, RaygenProgram program);
  ~Pipeline();
  Pipeline(const Pipeline&) = delete;
  Pipeline& operator=(const Pipeline&) = delete;

  OptixPipeline get() const { return pipeline_; }
  const OptixShaderBindingTable& bindingTable() const { return table_; }

 private:
  static constexpr int kGroupCount = 5;  // raygen, radiance/shadow miss, radiance/shadow hit group

  OptixProgramGroup groups_[kGroupCount] = {};
  OptixPipeline pipeline_ = nullptr;
  DeviceBuffer records_;
  OptixShaderBindingTable table_ = {};
};

}  // namespace candela::optix
