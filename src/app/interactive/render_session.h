#pragma once
#include <cstdint>
#include <memory>
#include <optional>

#include "app/interactive/scene_summary.h"
#include "backends/backend.h"
#include "backends/film_filters.h"
#include "scene/animation_player.h"
#include "scene/material_overrides.h"

namespace candela {

bool sameCamera(const Camera& a, const Camera& b);

// The viewer's hold on a backend. Every frame names the camera and settings it wants; when either differs from
// the previous frame's, or the scene or environment changed, the backend restarts its accumulation first.
class RenderSession {
 public:
  explicit RenderSession(std::unique_ptr<Backend> backend);

  void setScene(Scene scene);
  const Scene& scene() const { return scene_; }
  const SceneSummary& summary() const { return summary_; }

  // Multiplies the scene's own environment intensity and adds to its rotation; the backend gets the new
  // environment (Backend::setEnvironment, no rebuild of the geometry) only when one of them changes.
  void setEnvironment(float intensityScale, float extraRotationDegrees);
  // Renders the scene's own materials under `overrides`: the backend gets the new materials alone
  // (Backend::setMaterials), or the whole scene again where it cannot take them so.
  void setMaterialOverrides(const MaterialOverrides& overrides);

  // Poses the scene's animated instances, cameras, lights and deformed meshes for `clip` at `time`
  // (AnimationPlayer); the backend gets them (Backend::setInstanceTransforms, or setDeformedMeshes) with the next
  // frame, only when the pose is another one.
  // Returns whether it is.
  bool poseAnimation(int clip, float time);

  // Adds `samplesPerPixel` samples. With `accumulate` off every frame starts afresh with its own seed, so
  // successive frames show independent noise.
  FrameStats renderFrame(const Camera& camera, const RenderSettings& settings, uint32_t samplesPerPixel,
                         bool accumulate);

  uint32_t accumulatedSamples() const { return backend_->accumulatedSamples(); }
  const Camera& camera() const { return camera_; }  // of the last frame
  uint64_t restarts() const { return restarts_; }   // times accumulation started over
  uint64_t frames() const { return frames_; }
  const RenderSettings& appliedSettings() const { return applied_; }
  Image image() const { return backend_->readImage(); }
  // The part of image() the camera sees emitted (AOVs enabled).
  Image emission() const { return backend_->readEmission(); }
  // Starts or stops accumulating the AOVs; a change restarts the accumulation.
  void setAovsEnabled(bool enabled);
  // The accumulated image through the backend's a-trous denoiser (AOVs enabled).
  Image atrousImage(const AtrousParams& params) const { return backend_->filters().atrous(params); }
  const Backend& backend() const { return *backend_; }

 private:
  std::unique_ptr<Backend> backend_;
  Scene scene_;
  SceneSummary summary_;
  void applyEnvironment();
  void applyMaterials();
  std::optional<AnimationPlayer> player_;      // for a scene with an animation
  std::optional<std::pair<int, float>> pose_;  // the clip and time the instances are posed for; none: rest

  // What the scene was loaded with, and the viewer's adjustments to it.
  std::vector<Material> sceneMaterials_;
  float sceneIntensity_ = 1.0f;
  float sceneRotation_ = 0.0f;
  float intensityScale_ = 1.0f;
  float extraRotation_ = 0.0f;
  MaterialOverrides overrides_;

  bool sceneChanged_ = true;
  bool materialsChanged_ = false;
  bool environmentChanged_ = false;
  bool instancesChanged_ = false;
  bool haveFrame_ = false;
  Camera camera_;
  RenderSettings applied_;
  uint64_t restarts_ = 0;
  uint64_t frames_ = 0;
};

}  // namespace candela
