#pragma once
#include <cstddef>
#include <vector>

#include "core/bounds.h"
#include "scene/scene.h"

namespace candela {

// Poses the animated instances of a scene (Scene::animation) at a time. Backends keep a fixed list of
// instances, so an instance is never removed: one whose posed transform is singular (a node scaled to zero, as
// files do to hide a part) or places it beyond kMaxSceneCoordinate is shrunk to a millionth of its size instead,
// where it cannot be seen.
class AnimationPlayer {
 public:
  explicit AnimationPlayer(const Scene& scene);

  // Writes the transforms of the animated instances for `clip` (an index into Scene::animation.clips, or -1 for
  // the rest pose) at `time` seconds into scene.instances. Returns how many of them had to be hidden because
  // their transform would place them out of range (singular ones are not counted: scaling to zero is meant).
  size_t pose(Scene& scene, int clip, float time) const;

 private:
  std::vector<Bounds3> meshBounds_;  // per mesh of the scene
};

}  // namespace candela
