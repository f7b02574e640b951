#include "backends/optix/program_use.h"

namespace candela::optix {

std::vector<PipelineKind> pipelinesNeeded(const ProgramUse& use) {
  if (use.media) return {PipelineKind::Media};    // with or without AOVs
  if (use.restir) return {PipelineKind::Restir};  // with or without AOVs
  if (use.aovs) return {PipelineKind::AovMegakernel};
  switch (use.schedule) {
    case PathSchedule::Megakernel: return {PipelineKind::Megakernel};
    case PathSchedule::Wavefront: return {PipelineKind::Wavefront};
    case PathSchedule::Auto: break;
  }
  return {PipelineKind::Megakernel, PipelineKind::Wavefront};
}

std::vector<PipelineKind> pipelinesLikely(const ProgramUse& use) {
  if (use.restir || use.media) return {};
  if (use.aovs) return pipelinesNeeded({use.schedule, false, false});
  return {PipelineKind::AovMegakernel};
}

}  // namespace candela::optix
