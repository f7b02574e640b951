#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include <tbb/task_arena.h>

#include "app/interactive/scene_summary.h"
#include "backends/backend.h"
#include "backends/film_filters.h"
#include "scene/animation_player.h"
#include "scene/material_overrides.h"

namespace candela {

bool sameCamera(const Camera& a, const Camera& b);

// The viewer's hold on a backend. Every frame names the camera and settings it wants; when either differs from
// the previous frame's, or the scene or environment changed, the backend restarts its accumulation first.
//
// A GPU backend whose programs are still compiling (Backend::startingCompile: a first start on a machine) may come
// with a backend that renders meanwhile, the CPU's: every change goes to both, so that the GPU backend has the
// scene, camera and settings when its compile ends, and the frames render on the meanwhile one. The first frame
// after the compile has ended renders on the GPU backend, from an empty film (a restart), and the meanwhile one
// is dropped: the one handover a session has.
//
// `requested`: the backend the session was asked for (--backend). Where it is "auto" and the GPU backend cannot
// render a scene (SceneUnsupported), the CPU backend renders the session from then on (setSceneOrFallBack).
class RenderSession {
 public:
  explicit RenderSession(std::unique_ptr<Backend> backend, std::unique_ptr<Backend> meanwhile = nullptr,
                         std::string requested = "");

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

  uint32_t accumulatedSamples() const { return backend().accumulatedSamples(); }
  const Camera& camera() const { return camera_; }  // of the last frame
  uint64_t restarts() const { return restarts_; }   // times accumulation started over
  uint64_t frames() const { return frames_; }
  const RenderSettings& appliedSettings() const { return applied_; }
  Image image() const { return backend().readImage(); }
  // The part of image() the camera sees emitted (AOVs enabled).
  Image emission() const { return backend().readEmission(); }
  // Starts or stops accumulating the AOVs; a change restarts the accumulation.
  void setAovsEnabled(bool enabled);
  // The accumulated image through the backend's a-trous denoiser (AOVs enabled).
  Image atrousImage(const AtrousParams& params) const { return backend().filters().atrous(params); }
  // The backend the frames render on: the meanwhile one until the handover.
  const Backend& backend() const { return meanwhile_ ? *meanwhile_ : *backend_; }
  // While the frames render meanwhile: how the compile they wait for goes (nothing once it has ended).
  std::optional<ProgramCompileStatus> startingCompile() const;
  // Times the frames moved to another backend: the handover, and a move to the CPU (see the class).
  uint64_t backendChanges() const { return backendChanges_; }

 private:
  // Hands over to the backend once its compile has ended; returns whether it did.
  bool handOverWhenReady();
  // Applies `change` to every backend held; on the meanwhile one in its arena.
  template <class Change>
  void toEach(const Change& change);
  // Gives every backend held the scene, or moves the session to the CPU (see the class); returns whether it moved.
  bool setSceneOnEach();

  std::unique_ptr<Backend> backend_;
  std::unique_ptr<Backend> meanwhile_;
  std::string requested_;
  // The meanwhile backend's work runs at low priority, so that the compile it waits for keeps the threads it can
  // use, and the frames take the rest.
  tbb::task_arena meanwhileArena_{tbb::task_arena::automatic, 1, tbb::task_arena::priority::low};
  uint64_t backendChanges_ = 0;
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

// While the session renders meanwhile, what the front ends show: "GPU programs compiling, 12/40, 8.1 s: frames on
// the cpu backend meanwhile" (tasks done of those known); empty otherwise.
std::string meanwhileNote(const RenderSession& session);

}  // namespace candela
