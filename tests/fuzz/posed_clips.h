#pragma once
// Posing a loaded scene's animation for the targets whose loaders make one (gltf, scene_file): the first clips,
// each inside and past its time span, which moves animated instances, skinned and morphed meshes, cameras and
// lights away from their rest pose. The animation must be one the player accepts (validateAnimation) and the posed
// scene must stay valid: either check throws std::runtime_error, which stops the fuzzer.
#include <algorithm>
#include <cstddef>

#include "scene/animation.h"
#include "scene/animation_player.h"
#include "scene/scene.h"

namespace candela::fuzz {

// Enough clips to reach every kind of channel in a small input, few enough to keep an input fast.
constexpr size_t kPosedClips = 4;

inline void poseClips(Scene& scene) {
  validateAnimation(scene);
  const AnimationPlayer player(scene);
  const size_t clips = std::min(scene.animation.clips.size(), kPosedClips);
  for (size_t c = 0; c < clips; ++c) {
    const AnimationClip& clip = scene.animation.clips[c];
    for (float time : {0.5f * (clip.start + clip.end), clip.end + 1.0f}) {
      player.pose(scene, int(c), time);
      validateScene(scene);
    }
  }
}

}  // namespace candela::fuzz
