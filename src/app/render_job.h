#pragma once
#include <string>
#include <vector>

#include "app/checkpoint/render_control.h"
#include "app/denoising/denoiser_choice.h"
#include "app/device_list.h"
#include "app/schedule/sample_dispenser.h"
#include "backends/backend.h"
#include "image/filters/atrous.h"
#include "image/filters/bilateral.h"
#include "io/images/aov_io.h"
#include "io/path_confinement.h"
#include "scene/cache/scene_cache.h"
#include "scene/loaders/texture_limits.h"
#include "scene/material_overrides.h"
#include "scene/scene.h"

namespace candela {

class RenderTeam;

struct RenderJob {
  std::string sceneSpec = "cornell-box";
  std::string environmentPath;  // replaces the scene's environment when set
  std::string camera;           // the name or index of the scene's camera to take; empty: the first
  SceneCacheSettings sceneCache;
  OutsidePaths outsidePaths = OutsidePaths::Refused;  // whether models may refer to files outside their folders
  TextureLimits textureLimits;
  // Which settings the command line gave; the others may come from the scene file's render hints.
  struct {
    bool width = false, height = false, samplesPerPixel = false, maxDepth = false;
  } given;
  RenderSettings settings;
  uint32_t samplesPerPixel = 64;
  std::string backend = "auto";
  DeviceRequest devices;  // the GPUs of the optix backend
  MaterialOverrides materialOverrides;
  uint32_t warmupFrames = 0;  // untimed launches before the timed ones
  // A benchmark's: the timed launches wait for every program of the settings, so that each is by the schedule in
  // which the render settles (ProgramWait::EveryFrame); the warm-up launches may come sooner, by a stand-in.
  bool steadyTimedFrames = false;
  bool rawTrace = false;  // also time the backend's raw-trace mode (optix only)
  DenoiserChoice denoiser = DenoiserChoice::None;
  AtrousParams atrous;
  BilateralParams bilateral;
  std::vector<Aov> aovs;       // AOVs to keep in RenderOutcome::aovs
  RenderControl control;       // checkpoints, resumption, time limit
  RenderTeam* team = nullptr;  // the processes of a distributed render; null: this process renders alone
};

struct RenderOutcome {
  // What was rendered: the command line's settings, or the scene file's render hints where it gave none.
  RenderSettings settings;
  uint32_t samplesPerPixel = 0;  // in the image: fewer than asked for when the render stopped early
  RenderEnd end = RenderEnd::Complete;
  bool checkpointFailed = false;  // the last --checkpoint could not be written
  bool writes = true;             // false on the processes of a distributed render that do not hold the image
  Image image;
  AovImages aovs;  // when RenderJob::aovs is not empty
  FrameStats stats;
  double seconds = 0.0;  // rendering only: scene loading and acceleration-structure builds excluded
  // Until the first image: reading the scene (runRenderJob only), starting the backend (its device), and from
  // handing it the scene to the end of its first launch (acceleration structures, uploads, and the wait for the
  // programs that launch needs, compiled once scene, settings and AOVs are set: programCompileSeconds, part of
  // firstFrameSeconds; 0 for a backend with no programs to compile, and for one that compiled them at its start).
  double loadSeconds = 0.0;
  double backendStartSeconds = 0.0;
  double firstFrameSeconds = 0.0;
  double programCompileSeconds = 0.0;
  std::string backendName;
  std::string deviceName;
  std::string sceneName;
  bool sceneHasLightSource = true;              // hasLightSource of the scene rendered
  std::vector<double> frameMilliseconds;        // wall clock of each timed launch
  std::vector<double> deviceFrameMilliseconds;  // GPU time of each timed launch, where the backend measures it
  // On several devices: each one's GPU time for its share of each timed launch ([launch][device]), and the time
  // the final read took to add the other devices' films to the first one's.
  std::vector<std::vector<double>> perDeviceFrameMilliseconds;
  double combineMilliseconds = 0.0;
  uint64_t rawTraceRaysPerFrame = 0;  // with RenderJob::rawTrace
  std::vector<double> rawTraceMilliseconds;
};

// Loads the scene, builds the backend and accumulates the requested samples, one launch per sample per pixel,
// after `warmupFrames` untimed launches; then denoises when asked (the a-trous and OptiX denoisers guided by the
// AOVs, which are then accumulated too). Throws std::runtime_error on failure; a
// denoiser that cannot run is reported on stderr and the image is kept as rendered. With `job.control` it
// resumes from a checkpoint, writes checkpoints and may stop early (RenderOutcome::end); with `job.team`, this
// process renders its share, and only the writer's outcome holds the image.
RenderOutcome runRenderJob(const RenderJob& job, bool showProgress);
// Renders `scene` as runRenderJob does once it is loaded: with a new backend, or with `backend` where given,
// which must hold `scene` already (setScene or setInstanceTransforms).
RenderOutcome renderLoadedScene(const RenderJob& job, const Scene& scene, bool showProgress,
                                Backend* backend = nullptr);
// The first half of runRenderJob: the job's scene, loaded with the material overrides applied. `hinted` becomes
// `job` with the scene file's render hints where the command line gave none.
Scene loadSceneForJob(const RenderJob& job, RenderJob& hinted);
// Warns in one line where the outcome's scene has light but its image, as `display` shows it, is almost all black
// (looksUnlit): a camera inside a closed object, say, would otherwise give a black image without a word (a scene
// without light is named when it loads).
void warnWhereTheCameraSeesNoLight(const RenderOutcome& outcome, const DisplaySettings& display);

}  // namespace candela
