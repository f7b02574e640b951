#pragma once
#include <cstdint>

#include "app/render_job.h"

namespace candela {

// Host memory a render of `job` (its settings after the scene's hints) needs at its peak, beyond the scene:
// the film and the AOV sums the backend accumulates, the images read out of it, the denoiser's planes, and the
// encoded output. An estimate from the buffers' sizes, not a measurement.
uint64_t estimateRenderBytes(const RenderJob& job);

// Throws std::runtime_error, one line, when the estimate exceeds what is available: a render that would fail to
// allocate after hours of work is refused before it starts.
void checkRenderMemory(const RenderJob& job);

}  // namespace candela
