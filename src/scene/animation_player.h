#pragma once
#include <cstddef>
#include <vector>

#include "core/bounds.h"
#include "scene/scene.h"

namespace candela {

// Poses the animated instances, cameras and punctual lights of a scene (Scene::animation) at a time. Backends
// keep a fixed list of instances, so an instance is never removed: one whose posed transform is singular (a node
// scaled to zero, as files do to hide a part) or places it beyond kMaxSceneCoordinate is shrunk to a millionth of
// its size instead, where it cannot be seen. Likewise a light posed where it is unusable (no direction, or beyond
// kMaxSceneCoordinate) stays where it is at rest, switched off, and such a camera keeps its rest pose. Skinned and
// morphed meshes (SceneAnimation::deformations) get their deformed vertices; one that would leave the coordinate
// range takes its rest shape instead.
class AnimationPlayer {
 public:
  // Takes the rest pose of the animated cameras and lights from `scene`, as loaded.
  explicit AnimationPlayer(const Scene& scene);

  // Writes the transforms of the animated instances for `clip` (an index into Scene::animation.clips, or -1 for
  // the rest pose) at `time` seconds into scene.instances, the poses of the animated cameras and lights into
  // scene.cameras (and scene.camera where it is one of them, Scene::cameraIndex) and scene.punctualLights, and the
  // vertices of the deformed meshes into scene.meshes.
  // Returns how many instances had to be hidden because their transform would place them out of range
  // (singular ones are not counted: scaling to zero is meant).
  size_t pose(Scene& scene, int clip, float time) const;

  // The meshes whose vertices pose() writes (for Backend::setDeformedMeshes), in increasing order.
  const std::vector<uint32_t>& deformedMeshes() const { return deformedMeshes_; }

 private:
  void deform(Scene& scene, int clip, float time, const std::vector<Affine3x4>& world) const;

  std::vector<uint32_t> deformedMeshes_;
  std::vector<Bounds3> meshBounds_;             // per mesh of the scene
  std::vector<CameraDescription> restCameras_;  // per entry of SceneAnimation::cameras
  std::vector<PunctualLight> restLights_;       // per entry of SceneAnimation::lights
};

// Whether an animation moves the scene's camera (Scene::camera is an animated entry of Scene::cameras).
bool sceneCameraAnimated(const Scene& scene);

}  // namespace candela
