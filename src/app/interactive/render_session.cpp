#include "app/interactive/render_session.h"

#include <cstdio>
#include <utility>

#include "app/backend_factory.h"

namespace candela {

namespace {

bool sameVector(Vec3 a, Vec3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

bool sameSettings(const RenderSettings& a, const RenderSettings& b) {
  return a.width == b.width && a.height == b.height && a.maxDepth == b.maxDepth && a.rouletteDepth == b.rouletteDepth &&
         a.seed == b.seed && a.sampler == b.sampler && a.textureFilter == b.textureFilter;
}

}  // namespace

bool sameCamera(const Camera& a, const Camera& b) {
  return sameVector(a.position, b.position) && sameVector(a.forward, b.forward) && sameVector(a.right, b.right) &&
         sameVector(a.up, b.up) && a.lensRadius == b.lensRadius && a.focusDistance == b.focusDistance &&
         a.orthographic == b.orthographic;
}

RenderSession::RenderSession(std::unique_ptr<Backend> backend, std::unique_ptr<Backend> meanwhile,
                             std::string requested)
    : backend_(std::move(backend)), meanwhile_(std::move(meanwhile)), requested_(std::move(requested)) {}

template <class Change>
void RenderSession::toEach(const Change& change) {
  change(*backend_);
  if (meanwhile_) meanwhileArena_.execute([&] { change(*meanwhile_); });
}

std::optional<ProgramCompileStatus> RenderSession::startingCompile() const {
  return meanwhile_ ? backend_->startingCompile() : std::nullopt;
}

bool RenderSession::setSceneOnEach() {
  const bool aovs = backend().aovsEnabled();
  const Backend* before = backend_.get();
  std::string why;
  setSceneOrFallBack(backend_, requested_, scene_, why);
  if (backend_.get() == before) {
    if (meanwhile_) meanwhileArena_.execute([&] { meanwhile_->setScene(scene_); });
    return false;
  }
  std::fprintf(stderr, "%s\n", why.c_str());
  meanwhile_.reset();
  ++backendChanges_;
  backend_->setAovsEnabled(aovs);
  return true;
}

bool RenderSession::handOverWhenReady() {
  if (!meanwhile_ || backend_->startingCompile()) return false;
  meanwhile_.reset();
  ++backendChanges_;
  return true;
}

void RenderSession::setScene(Scene scene) {
  scene_ = std::move(scene);
  summary_ = summarizeScene(scene_);
  sceneMaterials_ = scene_.materials;
  player_.reset();
  if (!scene_.animation.empty()) player_.emplace(scene_);
  pose_.reset();
  instancesChanged_ = false;
  sceneIntensity_ = scene_.environment.intensity;
  sceneRotation_ = scene_.environment.rotationDegrees;
  applyEnvironment();
  applyMaterials();
  sceneChanged_ = true;
}

bool RenderSession::poseAnimation(int clip, float time) {
  if (!player_ || (pose_ && pose_->first == clip && pose_->second == time)) return false;
  player_->pose(scene_, clip, time);
  pose_ = {clip, time};
  instancesChanged_ = true;
  return true;
}

void RenderSession::setEnvironment(float intensityScale, float extraRotationDegrees) {
  if (intensityScale == intensityScale_ && extraRotationDegrees == extraRotation_) return;
  intensityScale_ = intensityScale;
  extraRotation_ = extraRotationDegrees;
  applyEnvironment();
}

void RenderSession::setMaterialOverrides(const MaterialOverrides& overrides) {
  overrides_ = overrides;
  applyMaterials();
}

void RenderSession::applyEnvironment() {
  scene_.environment.intensity = sceneIntensity_ * intensityScale_;
  scene_.environment.rotationDegrees = sceneRotation_ + extraRotation_;
  environmentChanged_ = true;
}

void RenderSession::applyMaterials() {
  scene_.materials = sceneMaterials_;
  applyOverrides(scene_.materials, overrides_);
  materialsChanged_ = true;
}

void RenderSession::setAovsEnabled(bool enabled) {
  if (enabled == backend().aovsEnabled()) return;
  toEach([&](Backend& b) { b.setAovsEnabled(enabled); });
  ++restarts_;
}

FrameStats RenderSession::renderFrame(const Camera& camera, const RenderSettings& settings, uint32_t samplesPerPixel,
                                      bool accumulate) {
  RenderSettings wanted = settings;
  if (!accumulate) wanted.seed = settings.seed + uint32_t(frames_);

  // The backend handed over to has every change already; its film is empty.
  bool restart = handOverWhenReady() || !haveFrame_ || !accumulate;
  if (!sceneChanged_ && materialsChanged_) {
    bool taken = true;
    toEach([&](Backend& b) { taken = b.setMaterials(scene_.materials) && taken; });
    if (!taken) sceneChanged_ = true;
  }
  if (!sceneChanged_ && environmentChanged_) toEach([&](Backend& b) { b.setEnvironment(scene_.environment); });
  if (!sceneChanged_ && instancesChanged_) {
    if (!player_->deformedMeshes().empty())
      toEach([&](Backend& b) { b.setDeformedMeshes(scene_, player_->deformedMeshes()); });
    else
      toEach([&](Backend& b) { b.setInstanceTransforms(scene_); });
  }
  // A backend that took over has none of the settings and camera yet.
  if (sceneChanged_ && setSceneOnEach()) haveFrame_ = false;
  if (sceneChanged_ || materialsChanged_ || environmentChanged_ || instancesChanged_) restart = true;
  sceneChanged_ = materialsChanged_ = environmentChanged_ = instancesChanged_ = false;
  if (!haveFrame_ || !sameSettings(wanted, applied_)) {
    toEach([&](Backend& b) { b.setSettings(wanted); });
    applied_ = wanted;
    restart = true;
  }
  if (!haveFrame_ || !sameCamera(camera, camera_)) {
    toEach([&](Backend& b) { b.setCamera(camera); });
    camera_ = camera;
    restart = true;
  }
  haveFrame_ = true;
  if (restart) ++restarts_;
  ++frames_;
  if (!meanwhile_) return backend_->render(samplesPerPixel);
  FrameStats stats;
  meanwhileArena_.execute([&] { stats = meanwhile_->render(samplesPerPixel); });
  return stats;
}

std::string meanwhileNote(const RenderSession& session) {
  const std::optional<ProgramCompileStatus> compile = session.startingCompile();
  if (!compile) return {};
  char note[160];
  std::snprintf(note, sizeof note, "GPU programs compiling, %u/%u, %.1f s: frames on the %s backend meanwhile",
                unsigned(compile->tasksDone), unsigned(compile->tasksKnown), compile->seconds,
                session.backend().name().c_str());
  return note;
}

}  // namespace candela
