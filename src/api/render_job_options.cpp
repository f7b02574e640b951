#include "api/render_job_options.h"

#include <string>

#include "app/denoising/denoiser_choice.h"
#include "candela/error.h"
#include "io/images/aov_io.h"
#include "scene/material_overrides.h"

namespace candela::api_detail {

namespace {

// The command line's ranges for the same options.
uint32_t checkedRange(const char* name, uint32_t value, uint32_t lowest, uint32_t highest) {
  if (value < lowest || value > highest)
    throw api::Error(std::string(name) + " " + std::to_string(value) + " is not in [" + std::to_string(lowest) + ", " +
                     std::to_string(highest) + "]");
  return value;
}

}  // namespace

RenderJob renderJobFor(const candela::Scene& scene, const api::RenderOptions& options,
                       uint32_t defaultSamplesPerPixel) {
  const RenderHints& hints = scene.renderHints;
  RenderJob job;
  RenderSettings& s = job.settings;
  s.width = checkedRange("width", options.width.value_or(hints.width.value_or(s.width)), 1, 16384);
  s.height = checkedRange("height", options.height.value_or(hints.height.value_or(s.height)), 1, 16384);
  s.maxDepth = checkedRange("max_depth", options.maxDepth.value_or(hints.maxDepth.value_or(s.maxDepth)), 1, 1024);
  s.seed = options.seed;
  job.samplesPerPixel =
      checkedRange("spp", options.samplesPerPixel.value_or(hints.samplesPerPixel.value_or(defaultSamplesPerPixel)), 1,
                   1u << 24);
  job.backend = options.backend;
  job.denoiser = parseDenoiser(options.denoiser);
  if (job.denoiser == DenoiserChoice::Temporal)
    throw api::Error("the temporal denoiser filters image sequences: use atrous, bilateral or optix for one image");
  if (!inThisBuild(job.denoiser)) throw api::Error(notInThisBuild(job.denoiser));
  std::string aovs;
  for (const std::string& aov : options.aovs) aovs += (aovs.empty() ? "" : ",") + aov;
  if (!aovs.empty()) job.aovs = parseAovList(aovs);
  if (!options.shading.empty()) job.materialOverrides.shading = parseShadingModel(options.shading);
  return job;
}

const candela::Scene& withOverrides(const candela::Scene& scene, const RenderJob& job, candela::Scene& copy) {
  if (job.materialOverrides.shading == ShadingModel::Own) return scene;
  copy = scene;
  applyOverrides(copy.materials, job.materialOverrides);
  return copy;
}

}  // namespace candela::api_detail
