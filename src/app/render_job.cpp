#include "app/render_job.h"

#include <chrono>
#include <cstdio>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>

#include "app/backend_factory.h"
#include "app/checkpoint/checkpoint_file.h"
#include "app/checkpoint/render_identity.h"
#include "app/checkpoint/stop_signals.h"
#include "app/denoising/film_denoiser.h"
#include "app/render_memory.h"
#include "app/scene_loading.h"
#include "app/schedule/local_schedule.h"
#include "app/schedule/render_team.h"
#include "app/schedule/scheduled_render.h"
#include "image/visible_pixels.h"

namespace candela {

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

bool needsAovs(const RenderJob& job) { return !job.aovs.empty() || needsAovs(job.denoiser); }

void readResult(const Backend& backend, const RenderJob& job, const Camera& camera, RenderOutcome& outcome) {
  FilmDenoiser denoiser(job.denoiser, {job.atrous, job.bilateral, {}});
  if (job.aovs.empty()) {
    outcome.image = denoiser.apply(backend, camera, /*filmContinues=*/false);
    return;
  }
  outcome.aovs = backend.readAovs();
  outcome.image = denoiser.apply(backend, camera, /*filmContinues=*/false, &outcome.aovs);
}

// The sample index the render starts at: 0, or the next one of the checkpoint it resumes from, whose film is
// then in `backend` (on the writer; the other processes of a team start with empty films).
uint32_t loadResumedFilm(const RenderJob& job, Backend& backend, const ExrAttributes& identity) {
  if (job.control.resumePath.empty()) return 0;
  return agreedStep(job.team, [&]() -> uint32_t {
    if (job.team && !job.team->writes()) return 0;
    const RenderSettings& s = job.settings;
    Checkpoint c = readCheckpoint(job.control.resumePath, identity, s.width, s.height, needsAovs(job));
    if (c.nextSample > job.samplesPerPixel)
      throw std::runtime_error("cannot resume from '" + job.control.resumePath + "': it holds " +
                               std::to_string(c.nextSample) + " samples per pixel, more than the " +
                               std::to_string(job.samplesPerPixel) + " asked for (--spp)");
    backend.loadFilm(c.film);
    return c.nextSample;
  });
}

// Renders the sample indices [first, end) under the job's control and team; fills the outcome's statistics.
ScheduledRenderResult accumulateSamples(const RenderJob& job, Backend& backend, uint32_t first, uint32_t end,
                                        const ExrAttributes& identity, bool showProgress,
                                        const std::function<FrameStats()>& render) {
  const auto timeLimitFrom = job.control.timeLimitFrom == std::chrono::steady_clock::time_point{}
                                 ? std::chrono::steady_clock::now()
                                 : job.control.timeLimitFrom;
  const SampleDispenser dispenser(first, end, job.control, timeLimitFrom);
  std::unique_ptr<SampleSchedule> schedule =
      job.team ? job.team->schedule(dispenser, showProgress) : std::make_unique<LocalSchedule>(dispenser, showProgress);
  std::optional<StopOnSignals> stopOnSignals;
  if (job.control.stopsOnSignals()) stopOnSignals.emplace();
  return renderScheduled(backend, *schedule, {job.control.checkpointPath, identity, job.samplesPerPixel}, render);
}

}  // namespace

RenderOutcome runRenderJob(const RenderJob& job, bool showProgress) {
  if (!inThisBuild(job.denoiser)) throw std::runtime_error(notInThisBuild(job.denoiser));
  const auto loadStart = std::chrono::steady_clock::now();
  RenderJob hinted;
  Scene scene = agreedStep(job.team, [&] { return loadSceneForJob(job, hinted); });
  const double loadSeconds = secondsSince(loadStart);
  hinted.control.timeLimitFrom = loadStart;
  RenderOutcome outcome = renderLoadedScene(hinted, scene, showProgress);
  outcome.loadSeconds = loadSeconds;
  return outcome;
}

void warnWhereTheCameraSeesNoLight(const RenderOutcome& outcome, const DisplaySettings& display) {
  if (outcome.sceneHasLightSource && looksUnlit(outcome.image, display))
    std::fprintf(stderr,
                 "candela: warning: the image is black in more than 99%% of its pixels: little of the scene's light "
                 "reaches what the camera sees (is the camera inside a closed object? --camera chooses another, "
                 "--exposure brightens the image)\n");
}

Scene loadSceneForJob(const RenderJob& job, RenderJob& hinted) {
  Scene scene = loadScene(job.sceneSpec, {job.environmentPath, job.sceneCache, job.outsidePaths, job.camera,
                                          job.textureLimits, !job.team || job.team->writes()});
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
  agreedStep(job.team, [&] {
    checkRenderMemory(job);
    return true;
  });
  RenderOutcome outcome;
  outcome.settings = job.settings;
  outcome.samplesPerPixel = job.samplesPerPixel;
  const auto backendStart = Clock::now();
  std::unique_ptr<Backend> created;
  if (!given) {
    std::string why;
    // Under mpirun each rank renders on one GPU: its local rank's.
    if (job.team && job.devices.given)
      throw std::runtime_error("--devices does not apply under mpirun: each rank renders on the GPU of its local rank");
    created = agreedStep(job.team, [&] {
      // The programs compile at the first frame, when what it renders is known (ProgramStart::AtFirstFrame).
      return job.team
                 ? createBackend(job.backend, why, job.team->localIndex(), compileProgressOnStderr(),
                                 ProgramStart::AtFirstFrame)
                 : createBackend(job.backend, why, job.devices, compileProgressOnStderr(), ProgramStart::AtFirstFrame);
    });
    if (!job.team || job.team->writes()) std::fprintf(stderr, "%s\n", why.c_str());
  }
  outcome.backendStartSeconds = secondsSince(backendStart);
  const auto setupStart = Clock::now();
  if (!given) {
    std::string why;
    setSceneOrFallBack(created, job.backend, scene, why);
    if (!why.empty() && (!job.team || job.team->writes())) std::fprintf(stderr, "%s\n", why.c_str());
  }
  Backend* backend = given ? given : created.get();
  if (job.rawTrace && !backend->supportsRawTrace())
    throw std::runtime_error("the raw-trace mode needs the optix backend, not " + backend->name());
  backend->setSettings(job.settings);
  backend->setAovsEnabled(needsAovs(job));
  const Camera camera = scene.camera.toCamera(float(job.settings.width) / float(job.settings.height));
  backend->setCamera(camera);
  outcome.programCompileSeconds = backend->preparePrograms();
  // render() returns when its launch has finished, on either backend.
  auto renderFrame = [&] {
    FrameStats frame = backend->render(1);
    if (outcome.firstFrameSeconds == 0.0) outcome.firstFrameSeconds = secondsSince(setupStart);
    return frame;
  };

  const ExrAttributes identity = renderIdentity(job, needsAovs(job));
  if (job.team) job.team->checkSameRender(teamIdentity(job, scene, needsAovs(job)));
  // Warm-up launches take the first sample indices, and the timed ones continue after them.
  const uint32_t first = loadResumedFilm(job, *backend, identity) + job.warmupFrames;
  for (uint32_t w = 0; w < job.warmupFrames; ++w) renderFrame();
  if (job.steadyTimedFrames) {
    const double waited = backend->preparePrograms(ProgramWait::EveryFrame);
    if (outcome.firstFrameSeconds == 0.0) outcome.programCompileSeconds += waited;
  }
  auto start = Clock::now();
  ScheduledRenderResult rendered = accumulateSamples(job, *backend, first, job.samplesPerPixel + job.warmupFrames,
                                                     identity, showProgress, renderFrame);
  outcome.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  outcome.samplesPerPixel = rendered.samples - job.warmupFrames;
  outcome.end = rendered.end;
  outcome.checkpointFailed = rendered.checkpointFailed;
  outcome.writes = rendered.writes;
  outcome.stats = rendered.stats;
  outcome.frameMilliseconds = std::move(rendered.frameMilliseconds);
  outcome.deviceFrameMilliseconds = std::move(rendered.deviceFrameMilliseconds);
  outcome.perDeviceFrameMilliseconds = std::move(rendered.perDeviceFrameMilliseconds);
  outcome.backendName = backend->name();
  outcome.deviceName = backend->deviceName();
  outcome.sceneName = scene.name;
  outcome.sceneHasLightSource = hasLightSource(scene);
  if (!outcome.writes) return outcome;
  if (job.rawTrace) {
    RawTraceTiming timing = backend->timeRawTrace(job.warmupFrames, job.samplesPerPixel);
    outcome.rawTraceRaysPerFrame = timing.raysPerFrame;
    outcome.rawTraceMilliseconds = std::move(timing.deviceMilliseconds);
  }
  readResult(*backend, job, camera, outcome);
  outcome.combineMilliseconds = backend->lastCombineMilliseconds();
  return outcome;
}

}  // namespace candela
