#include "app/render_job.h"

#include <chrono>
#include <cstdio>

#include "app/backend_factory.h"
#include "app/progress.h"
#include "app/scene_loading.h"

namespace candela {

RenderOutcome runRenderJob(const RenderJob& job, bool showProgress) {
  Scene scene = loadScene(job.sceneSpec, {job.environmentPath});
  applyOverrides(scene.materials, job.materialOverrides);
  RenderJob hinted = job;
  const RenderHints& hints = scene.renderHints;
  if (hints.width && !job.given.width) hinted.settings.width = *hints.width;
  if (hints.height && !job.given.height) hinted.settings.height = *hints.height;
  if (hints.samplesPerPixel && !job.given.samplesPerPixel) hinted.samplesPerPixel = *hints.samplesPerPixel;
  if (hints.maxDepth && !job.given.maxDepth) hinted.settings.maxDepth = *hints.maxDepth;
  return renderLoadedScene(hinted, scene, showProgress);
}

RenderOutcome renderLoadedScene(const RenderJob& job, const Scene& scene, bool showProgress) {
  std::string why;
  std::unique_ptr<Backend> backend = createBackend(job.backend, why);
  std::fprintf(stderr, "%s\n", why.c_str());
  backend->setScene(scene);
  backend->setSettings(job.settings);
  backend->setCamera(scene.camera.toCamera(float(job.settings.width) / float(job.settings.height)));

  RenderOutcome outcome;
  ProgressReporter progress("rendering", job.samplesPerPixel);
  auto start = std::chrono::steady_clock::now();
  for (uint32_t s = 0; s < job.samplesPerPixel; ++s) {
    FrameStats frame = backend->render(1);
    outcome.stats.rays += frame.rays;
    outcome.stats.invalidSamples += frame.invalidSamples;
    if (showProgress) progress.update(s + 1);
  }
  outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (showProgress) progress.finish();
  outcome.image = backend->readImage();
  outcome.backendName = backend->name();
  outcome.deviceName = backend->deviceName();
  outcome.sceneName = scene.name;
  return outcome;
}

}  // namespace candela
