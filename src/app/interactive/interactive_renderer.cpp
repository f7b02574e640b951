#include "app/interactive/interactive_renderer.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <utility>

#include "app/backend_factory.h"
#include "app/interactive/post_filter.h"
#include "app/interactive/viewer_files.h"
#include "app/scene_loading.h"
#include "scene/animation_player.h"

namespace candela {

InteractiveRenderer::Backends InteractiveRenderer::makeBackends(const InteractiveOptions& options) {
  Backends backends;
  std::string why;
  backends.backend =
      createBackend(options.backend, why, options.devices, compileProgressOnStderr(), ProgramStart::InBackground);
  std::fprintf(stderr, "%s\n", why.c_str());
  if (backends.backend->startingCompile()) {
    backends.meanwhile = createBackend("cpu", why);
    std::fprintf(stderr, "backend: cpu meanwhile, until the GPU programs have compiled\n");
  }
  return backends;
}

InteractiveRenderer::InteractiveRenderer(const InteractiveOptions& options, Backends backends)
    : options_(options), session_(std::move(backends.backend), std::move(backends.meanwhile), options.backend) {}

InteractiveRenderer::InteractiveRenderer(const InteractiveOptions& options)
    : InteractiveRenderer(options, makeBackends(options)) {
  controls_.maxDepth = options.maxDepth;
  controls_.samplesPerFrame = options.samplesPerFrame;
  controls_.post = options.post;
  showScene(loadScene(options.sceneSpec, {options.environmentPath, options.sceneCache, options.outsidePaths,
                                          options.camera, options.textureLimits}),
            options.sceneSpec);
  if (options.animation.empty()) return;
  const Scene& scene = session_.scene();
  if (scene.animation.empty())
    throw std::runtime_error(scene.name + ": no animation '" + options.animation + "' (it has none)");
  selectClip(controls_.animation, scene.animation, int(findClip(scene.animation, options.animation)));
}

void InteractiveRenderer::openScene(const std::string& spec) {
  showScene(loadScene(spec, {{}, options_.sceneCache, options_.outsidePaths, {}, options_.textureLimits}), spec);
}

void InteractiveRenderer::showScene(Scene scene, const std::string& spec) {
  validateScene(scene);
  camera_ = std::make_unique<OrbitCamera>(scene.camera, summarizeScene(scene).bounds);
  followsSceneCamera_ = sceneCameraAnimated(scene);
  controls_.animation = {};
  if (!scene.animation.empty()) selectClip(controls_.animation, scene.animation, 0);
  sceneSpec_ = spec;
  sceneJustShown_ = true;
  session_.setScene(std::move(scene));
}

void InteractiveRenderer::frameScene() {
  camera_->frameScene();
  followsSceneCamera_ = false;
}

void InteractiveRenderer::resetCamera() {
  camera_ = std::make_unique<OrbitCamera>(session_.scene().camera, session_.summary().bounds);
  followsSceneCamera_ = sceneCameraAnimated(session_.scene());
}

void InteractiveRenderer::applyEnvironmentControls() {
  session_.setEnvironment(controls_.environmentScale, controls_.environmentRotation);
}

void InteractiveRenderer::applyMaterialControls() { session_.setMaterialOverrides(controls_.materials); }

FrameOutcome InteractiveRenderer::step(const FrameRequest& request, FrontEnd& frontEnd) {
  // A playing animation moves on with the wall clock; a new pose restarts the accumulation like a camera move.
  bool posed = false;
  if (const SceneAnimation& animation = session_.scene().animation; !animation.empty()) {
    advanceAnimation(controls_.animation, animation, request.seconds);
    posed = session_.poseAnimation(controls_.animation.clip, controls_.animation.time);
  }
  // The view follows an animated scene camera until the user moves it (resetCamera goes back to it).
  if (posed && followsSceneCamera_)
    camera_ = std::make_unique<OrbitCamera>(session_.scene().camera, session_.summary().bounds);
  const FlyKeys flyKeys = frontEnd.takeInput();
  const float aspect = float(request.width) / float(request.height);
  const Camera beforeInput = camera_->camera(aspect);
  input_.apply(*camera_, flyKeys, float(std::min(request.seconds, kMaxFlyStep)), float(request.height));
  const Camera camera = camera_->camera(aspect);
  if (!sameCamera(camera, beforeInput)) followsSceneCamera_ = false;
  // A scene's first camera is where the view starts, not a motion.
  const bool moved = (!sceneJustShown_ && !sameCamera(camera, lastCamera_)) || (posed && controls_.animation.playing);
  lastCamera_ = camera;
  sceneJustShown_ = false;

  FrameOutcome outcome;
  outcome.plan = policy_.plan(request.width, request.height, controls_.samplesPerFrame, moved, request.now);
  frontEnd.adjustPlan(outcome.plan);
  RenderSettings settings;
  settings.width = outcome.plan.width;
  settings.height = outcome.plan.height;
  settings.maxDepth = controls_.maxDepth;
  settings.seed = options_.seed;
  settings.sampler = options_.sampler;
  settings.lightSampler = options_.lightSampler;
  settings.restir = options_.restir;
  const auto start = std::chrono::steady_clock::now();
  prepareDenoiser(frontEnd);
  // The bilateral filter keeps the emission apart, which the backend records with the AOVs.
  session_.setAovsEnabled(controls_.post.denoiser != DenoiserChoice::None || controls_.post.bilateral);
  const auto renderStart = std::chrono::steady_clock::now();
  session_.renderFrame(camera, settings, outcome.plan.samplesPerPixel, controls_.accumulate);
  outcome.renderSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - renderStart).count();
  FrameImages images(session_, denoiser_, controls_.post);
  frontEnd.present(images);
  outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  policy_.recordFrame(outcome.plan, outcome.seconds);
  return outcome;
}

// The OptiX AI denoiser is made when first chosen; where it cannot run the front end says why and denoising goes
// off, before any frame is rendered for it.
void InteractiveRenderer::prepareDenoiser(FrontEnd& frontEnd) {
  const std::string why = denoiser_.prepareOrTurnOff(controls_.post.denoiser);
  if (!why.empty()) frontEnd.report(why, true);
}

Image InteractiveRenderer::accumulatedImage() {
  return denoiser_.apply(session_, controls_.post.denoiser, controls_.post.atrousParams);
}

Image InteractiveRenderer::recordedEmission() const {
  return session_.backend().aovsEnabled() ? session_.emission() : Image();
}

Image InteractiveRenderer::postImage() { return postFiltered(accumulatedImage(), recordedEmission(), controls_.post); }

void InteractiveRenderer::writeScreenshot(const std::string& path) {
  saveScreenshot(path, accumulatedImage(), recordedEmission(), controls_.post);
}

}  // namespace candela
