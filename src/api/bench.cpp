#include <algorithm>
#include <optional>

#include <tbb/global_control.h>

#include "api/error_translation.h"
#include "api/render_job_options.h"
#include "api/scene_data.h"
#include "candela/render.h"

namespace candela::api {

namespace {

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const size_t middle = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + long(middle), values.end());
  return values[middle];
}

}  // namespace

BenchResult bench(const Scene& scene, const RenderOptions& options, uint32_t warmupFrames) {
  return withErrorsTranslated("bench", [&] {
    RenderJob job = api_detail::renderJobFor(scene.data().scene, options, 16);
    job.warmupFrames = warmupFrames;
    std::optional<tbb::global_control> threads;
    if (options.threads > 0) threads.emplace(tbb::global_control::max_allowed_parallelism, options.threads);
    candela::Scene copy;
    const RenderOutcome outcome =
        renderLoadedScene(job, api_detail::withOverrides(scene.data().scene, job, copy), false);
    BenchResult result;
    result.scene = outcome.sceneName;
    result.backend = outcome.backendName;
    result.device = outcome.deviceName;
    result.width = outcome.settings.width;
    result.height = outcome.settings.height;
    result.samplesPerPixel = outcome.samplesPerPixel;
    result.maxDepth = outcome.settings.maxDepth;
    result.seconds = outcome.seconds;
    const double samples = double(result.width) * result.height * result.samplesPerPixel;
    result.msamplesPerSecond = samples / outcome.seconds / 1e6;
    result.mraysPerSecond = double(outcome.stats.rays) / outcome.seconds / 1e6;
    result.invalidSamples = outcome.stats.invalidSamples;
    result.medianMsPerFrame = median(outcome.frameMilliseconds);
    result.backendStartSeconds = outcome.backendStartSeconds;
    result.firstFrameSeconds = outcome.firstFrameSeconds;
    return result;
  });
}

}  // namespace candela::api
