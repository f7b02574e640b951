#include "app/camera_path_render.h"

#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "app/backend_factory.h"
#include "app/camera_path.h"
#include "app/denoising/film_denoiser.h"
#include "app/scene_loading.h"

namespace candela {

namespace {

// The scene file's render hints where the command line gave no setting, as for one image (render_job.cpp).
RenderJob withHints(RenderJob job, const RenderHints& hints) {
  if (hints.width && !job.given.width) job.settings.width = *hints.width;
  if (hints.height && !job.given.height) job.settings.height = *hints.height;
  if (hints.samplesPerPixel && !job.given.samplesPerPixel) job.samplesPerPixel = *hints.samplesPerPixel;
  if (hints.maxDepth && !job.given.maxDepth) job.settings.maxDepth = *hints.maxDepth;
  return job;
}

}  // namespace

void runCameraPathRender(const RenderJob& pathJob, const TemporalParams& temporalParams, const CameraPathSource& source,
                         const std::string& output, const DisplaySettings& display) {
  FilmDenoiser denoiser(pathJob.denoiser, {pathJob.atrous, pathJob.bilateral, temporalParams});
  validateTemporalParams(temporalParams);
  Scene scene = loadScene(pathJob.sceneSpec, {pathJob.environmentPath, pathJob.sceneCache, pathJob.outsidePaths,
                                              pathJob.camera, pathJob.textureLimits});
  applyOverrides(scene.materials, pathJob.materialOverrides);
  const RenderJob job = withHints(pathJob, scene.renderHints);
  const std::vector<CameraDescription> path =
      source.file.empty() ? orbitCameraPath(scene.camera, source.orbitFrames, source.orbitDegrees)
                          : readCameraPath(source.file, scene.camera);
  // Every frame's file must be writable before the first frame is rendered.
  for (size_t i = 0; i < path.size(); ++i) checkAtomicTarget(frameFileName(output, i, path.size()));

  std::string why;
  std::unique_ptr<Backend> backend = createBackend(job.backend, why, job.devices);
  if (!why.empty()) std::fprintf(stderr, "%s\n", why.c_str());
  why.clear();
  setSceneOrFallBack(backend, job.backend, scene, why);
  if (!why.empty()) std::fprintf(stderr, "%s\n", why.c_str());
  backend->setSettings(job.settings);
  backend->setAovsEnabled(needsAovs(job.denoiser));
  const float aspect = float(job.settings.width) / float(job.settings.height);
  for (size_t i = 0; i < path.size(); ++i) {
    const Camera camera = path[i].toCamera(aspect);
    backend->setCamera(camera);  // restarts the film
    for (uint32_t s = 0; s < job.samplesPerPixel; ++s) backend->render(1);
    const std::string file = frameFileName(output, i, path.size());
    // Each frame's film starts afresh: the temporal filter's history is reprojected, not continued.
    writeImage(file, denoiser.apply(*backend, camera, /*filmContinues=*/false), display);
    std::printf("%s\n", std::filesystem::absolute(file).string().c_str());
    std::fflush(stdout);
  }
}

}  // namespace candela
