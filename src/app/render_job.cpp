#include "app/render_job.h"

#include <chrono>
#include <cstdio>
#include <stdexcept>

#include "app/backend_factory.h"
#include "app/progress.h"
#include "app/render_memory.h"
#include "app/scene_loading.h"
#if CANDELA_HAS_OPTIX
#include "backends/optix/optix_denoiser.h"
#endif

namespace candela {

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

bool needsAovs(const RenderJob& job) {
  return !job.aovs.empty() || job.denoiser == "atrous" || job.denoiser == "optix";
}

// Builds without OptiX refuse --denoise optix before rendering (runRenderJob).
void denoiseWithOptixGuides([[maybe_unused]] RenderOutcome& outcome, [[maybe_unused]] const AovImages& aovs) {
#if CANDELA_HAS_OPTIX
  try {
    outcome.image = denoiseWithOptix(outcome.image, {&aovs.albedo, &aovs.normal});
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "candela: %s; the image is kept without denoising\n", e.what());
  }
#endif
}

void readResult(const Backend& backend, const RenderJob& job, RenderOutcome& outcome) {
  if (job.denoiser == "atrous")
    outcome.image = backend.readAtrousDenoised(job.atrous);
  else if (job.denoiser == "bilateral")
    outcome.image = backend.readBilateralFiltered(job.bilateral);
  else
    outcome.image = backend.readImage();
  if (!needsAovs(job)) return;
  AovImages aovs = backend.readAovs();
  if (job.denoiser == "optix") denoiseWithOptixGuides(outcome, aovs);
  if (!job.aovs.empty()) outcome.aovs = std::move(aovs);
}

}  // namespace

RenderOutcome runRenderJob(const RenderJob& job, bool showProgress) {
#if !CANDELA_HAS_OPTIX
  if (job.denoiser == "optix")
    throw std::runtime_error(
        "--denoise optix needs the OptiX backend, which is not in this build (see README, "
        "'GPU backend')");
#endif
  const auto loadStart = std::chrono::steady_clock::now();
  RenderJob hinted;
  Scene scene = loadSceneForJob(job, hinted);
  const double loadSeconds = secondsSince(loadStart);
  RenderOutcome outcome = renderLoadedScene(hinted, scene, showProgress);
  outcome.loadSeconds = loadSeconds;
  return outcome;
}

Scene loadSceneForJob(const RenderJob& job, RenderJob& hinted) {
  Scene scene =
      loadScene(job.sceneSpec, {job.environmentPath, job.sceneCache, job.outsidePaths, job.camera, job.textureLimits});
  applyOverrides(scene.materials, job.materialOverrides);
  hinted = job;
  const RenderHints& hints = scene.renderHints;
  if (hints.width && !job.given.width) hinted.settings.width = *hints.width;
  if (hints.height && !job.given.height) hinted.settings.height = *hints.height;
  if (hints.samplesPerPixel && !job.given.samplesPerPixel) hinted.samplesPerPixel = *hints.samplesPerPixel;
  if (hints.maxDepth && !job.given.maxDepth) hinted.settings.maxDepth = *hints.maxDepth;
  return scene;
}

RenderOutcome renderLoadedScene(const RenderJob& job, const Scene& scene, bool showProgress, Backend* given) {
  using Clock = std::chrono::steady_clock;
  checkRenderMemory(job);
  RenderOutcome outcome;
  outcome.settings = job.settings;
  outcome.samplesPerPixel = job.samplesPerPixel;
  const auto backendStart = Clock::now();
  std::unique_ptr<Backend> created;
  if (!given) {
    std::string why;
    created = createBackend(job.backend, why);
    std::fprintf(stderr, "%s\n", why.c_str());
  }
  Backend* backend = given ? given : created.get();
  outcome.backendStartSeconds = secondsSince(backendStart);
  if (job.rawTrace && !backend->supportsRawTrace())
    throw std::runtime_error("the raw-trace mode needs the optix backend, not " + backend->name());
  const auto setupStart = Clock::now();
  if (!given) backend->setScene(scene);
  backend->setSettings(job.settings);
  backend->setAovsEnabled(needsAovs(job));
  backend->setCamera(scene.camera.toCamera(float(job.settings.width) / float(job.settings.height)));
  // render() returns when its launch has finished, on either backend.
  auto renderFrame = [&] {
    FrameStats frame = backend->render(1);
    if (outcome.firstFrameSeconds == 0.0) outcome.firstFrameSeconds = secondsSince(setupStart);
    return frame;
  };

  for (uint32_t w = 0; w < job.warmupFrames; ++w) renderFrame();
  ProgressReporter progress("rendering", job.samplesPerPixel);
  auto start = Clock::now();
  for (uint32_t s = 0; s < job.samplesPerPixel; ++s) {
    auto frameStart = Clock::now();
    FrameStats frame = renderFrame();
    outcome.frameMilliseconds.push_back(std::chrono::duration<double, std::milli>(Clock::now() - frameStart).count());
    if (frame.deviceMilliseconds > 0.0) outcome.deviceFrameMilliseconds.push_back(frame.deviceMilliseconds);
    outcome.stats.rays += frame.rays;
    outcome.stats.invalidSamples += frame.invalidSamples;
    if (showProgress) progress.update(s + 1);
  }
  outcome.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  if (showProgress) progress.finish();
  if (job.rawTrace) {
    RawTraceTiming timing = backend->timeRawTrace(job.warmupFrames, job.samplesPerPixel);
    outcome.rawTraceRaysPerFrame = timing.raysPerFrame;
    outcome.rawTraceMilliseconds = std::move(timing.deviceMilliseconds);
  }
  readResult(*backend, job, outcome);
  outcome.backendName = backend->name();
  outcome.deviceName = backend->deviceName();
  outcome.sceneName = scene.name;
  return outcome;
}

}  // namespace candela
