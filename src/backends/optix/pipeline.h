#pragma once
// The OptiX module built from the embedded OptiX-IR, its program groups, the pipeline and the shader binding
// tables: one per raygen program, sharing the miss and hit-group records.
#include <optix_types.h>

#include "backends/optix/device_buffer.h"

namespace candela::optix {

enum class RaygenProgram { Render = 0, Record, RawTrace, Count };

class Pipeline {
 public:
  explicit Pipeline(OptixDeviceContext context);
  ~Pipeline();
  Pipeline(const Pipeline&) = delete;
  Pipeline& operator=(const Pipeline&) = delete;

  OptixPipeline get() const { return pipeline_; }
  const OptixShaderBindingTable& bindingTable(RaygenProgram program) const { return tables_[int(program)]; }

 private:
  static constexpr int kRaygenCount = int(RaygenProgram::Count);
  static constexpr int kGroupCount = kRaygenCount + 4;  // + radiance/shadow miss, radiance/shadow hit group

  OptixModule module_ = nullptr;
  OptixProgramGroup groups_[kGroupCount] = {};
  OptixPipeline pipeline_ = nullptr;
  DeviceBuffer records_;
  OptixShaderBindingTable tables_[kRaygenCount] = {};
};

}  // namespace candela::optix
