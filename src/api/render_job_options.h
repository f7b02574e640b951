#pragma once
#include <cstdint>

#include "app/render_job.h"
#include "candela/render.h"

namespace candela::api_detail {

// The render job `candela render` would run for `options` on `scene`: unset sizes, samples and depth from the
// scene's render hints, else the command's defaults (`defaultSamplesPerPixel`: render's 64, bench's 16). Throws
// Error naming the first bad option.
RenderJob renderJobFor(const candela::Scene& scene, const api::RenderOptions& options, uint32_t defaultSamplesPerPixel);

// `scene`, or a copy with the job's material overrides applied where it has any.
const candela::Scene& withOverrides(const candela::Scene& scene, const RenderJob& job, candela::Scene& copy);

}  // namespace candela::api_detail
