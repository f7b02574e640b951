#include "app/viewer/render_session.h"

#include <utility>

namespace candela {

namespace {

bool sameVector(Vec3 a, Vec3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

bool sameCamera(const Camera& a, const Camera& b) {
  return sameVector(a.position, b.position) && sameVector(a.forward, b.forward) && sameVector(a.right, b.right) &&
         sameVector(a.up, b.up);
}

bool sameSettings(const RenderSettings& a, const RenderSettings& b) {
  return a.width == b.width && a.height == b.height && a.maxDepth == b.maxDepth &&
         a.rouletteDepth == b.rouletteDepth && a.seed == b.seed;
}

}  // namespace

RenderSession::RenderSession(std::unique_ptr<Backend> backend) : backend_(std::move(backend)) {}

void RenderSession::setScene(Scene scene) {
  scene_ = std::move(scene);
  summary_ = summarizeScene(scene_);
  sceneEnvironment_ = scene_.environment.radiance;
  scene_.environment.radiance = sceneEnvironment_ * environmentIntensity_;
  sceneChanged_ = true;
}

void RenderSession::setEnvironmentIntensity(float intensity) {
  if (intensity == environmentIntensity_) return;
  environmentIntensity_ = intensity;
  scene_.environment.radiance = sceneEnvironment_ * intensity;
  sceneChanged_ = true;
}

FrameStats RenderSession::renderFrame(const Camera& camera, const RenderSettings& settings,
                                      uint32_t samplesPerPixel, bool accumulate) {
  RenderSettings wanted = settings;
  if (!accumulate) wanted.seed = settings.seed + uint32_t(frames_);

  bool restart = !haveFrame_ || !accumulate;
  if (sceneChanged_) {
    backend_->setScene(scene_);
    sceneChanged_ = false;
    restart = true;
  }
  if (!haveFrame_ || !sameSettings(wanted, applied_)) {
    backend_->setSettings(wanted);
    applied_ = wanted;
    restart = true;
  }
  if (!haveFrame_ || !sameCamera(camera, camera_)) {
    backend_->setCamera(camera);
    camera_ = camera;
    restart = true;
  }
  haveFrame_ = true;
  if (restart) ++restarts_;
  ++frames_;
  return backend_->render(samplesPerPixel);
}

}  // namespace candela
