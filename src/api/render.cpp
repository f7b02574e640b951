#include "candela/render.h"

#include <chrono>
#include <memory>
#include <optional>

#include <tbb/global_control.h>

#include "api/error_translation.h"
#include "api/image_conversion.h"
#include "api/render_job_options.h"
#include "api/scene_data.h"
#include "app/backend_factory.h"
#include "app/denoising/film_denoiser.h"
#include "app/render_memory.h"

namespace candela::api {

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The AOVs the job asked for, by their names.
void keepAovs(const RenderJob& job, AovImages& aovs, RenderResult& result) {
  const uint32_t width = aovs.width(), height = aovs.height();
  for (Aov aov : job.aovs) {
    if (aov == Aov::Albedo) result.aovs[aovName(aov)] = api_detail::sharedImage(std::move(aovs.albedo));
    if (aov == Aov::Normal) result.aovs[aovName(aov)] = api_detail::sharedImage(std::move(aovs.normal));
    if (aov == Aov::Depth) result.aovs[aovName(aov)] = api_detail::sharedPlane(width, height, std::move(aovs.depth));
  }
}

// The backend set up as renderLoadedScene sets it up, then one launch of one sample per pixel at a time from
// sample index 0, as `candela render` on one process: the same seed gives the command's image bit for bit. The
// callback hears of each sample and may end the render.
RenderResult renderProgressively(const RenderJob& job, const candela::Scene& scene, const ProgressCallback& progress) {
  checkRenderMemory(job);
  std::string why;
  std::unique_ptr<Backend> backend = createBackend(job.backend, why, job.devices);
  backend->setScene(scene);
  backend->setSettings(job.settings);
  backend->setAovsEnabled(!job.aovs.empty() || needsAovs(job.denoiser));
  const candela::Camera camera = scene.camera.toCamera(float(job.settings.width) / float(job.settings.height));
  backend->setCamera(camera);

  RenderResult result;
  const auto start = std::chrono::steady_clock::now();
  Progress state;
  state.samplesPerPixel = job.samplesPerPixel;
  state.image = [&backend] { return api_detail::sharedImage(backend->readImage()); };
  while (result.samplesPerPixel < job.samplesPerPixel) {
    const FrameStats frame = backend->render(1);
    result.rays += frame.rays;
    result.invalidSamples += frame.invalidSamples;
    ++result.samplesPerPixel;
    if (!progress) continue;
    state.samples = result.samplesPerPixel;
    state.seconds = secondsSince(start);
    if (!progress(state)) break;
  }
  FilmDenoiser denoiser(job.denoiser, {job.atrous, job.bilateral, {}});
  if (job.aovs.empty()) {
    result.image = api_detail::sharedImage(denoiser.apply(*backend, camera, /*filmContinues=*/false));
  } else {
    AovImages aovs = backend->readAovs();
    result.image = api_detail::sharedImage(denoiser.apply(*backend, camera, /*filmContinues=*/false, &aovs));
    keepAovs(job, aovs, result);
  }
  result.seconds = secondsSince(start);
  result.backend = backend->name();
  result.device = backend->deviceName();
  return result;
}

}  // namespace

RenderResult render(const Scene& scene, const RenderOptions& options, const ProgressCallback& progress) {
  return withErrorsTranslated("render", [&] {
    const RenderJob job = api_detail::renderJobFor(scene.data().scene, options, 64);
    std::optional<tbb::global_control> threads;
    if (options.threads > 0) threads.emplace(tbb::global_control::max_allowed_parallelism, options.threads);
    candela::Scene copy;
    return renderProgressively(job, api_detail::withOverrides(scene.data().scene, job, copy), progress);
  });
}

}  // namespace candela::api
