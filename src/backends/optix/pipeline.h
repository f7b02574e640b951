#pragma once
// Pipelines that each hold some of the raygen programs with a shader binding table for each. OptiX compiles and
// sizes every pipeline on its own, so the raw-trace ceiling can be kept apart from the path tracer's shading code.
#include <optix_types.h>

#include <vector>

#include "backends/optix/device_buffer.h"
#include "backends/optix/program_modules.h"
#include "backends/optix/program_use.h"

namespace candela::optix {

// A pipeline holding some of the raygen programs, with one shader binding table for each; the tables share
// the miss and hit-group records.
class Pipeline {
 public:
  // Waits for the modules it needs (ProgramModules::get), and throws as it does. `lean`: of the lean kernel's
  // modules (moduleHolding).
  Pipeline(OptixDeviceContext context, ProgramModules& modules, const std::vector<RaygenProgram>& programs, bool lean);
  ~Pipeline();
  Pipeline(const Pipeline&) = delete;
  Pipeline& operator=(const Pipeline&) = delete;

  OptixPipeline get() const { return pipeline_; }
  const OptixShaderBindingTable& bindingTable(RaygenProgram program) const;

 private:
  std::vector<RaygenProgram> programs_;
  std::vector<OptixProgramGroup> groups_;  // the raygen programs in order, then radiance/shadow miss and hit
  OptixPipeline pipeline_ = nullptr;
  DeviceBuffer records_;
  std::vector<OptixShaderBindingTable> tables_;  // one per raygen program
};

}  // namespace candela::optix
