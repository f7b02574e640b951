#include "scene/animation_player.h"

#include <cmath>

#include "scene/scene_repair.h"

namespace candela {

namespace {

// What a hidden instance is scaled by: far below a pixel for any scene of sensible size, yet far from singular
// (kMinInstanceScale).
constexpr float kHiddenScale = 1e-6f;

// `transform` with its linear part replaced by kHiddenScale; its translation stays where it is usable.
Affine3x4 hidden(const Affine3x4& transform, const Bounds3& bounds) {
  Affine3x4 h;
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 3; ++col) h.m[4 * row + col] = row == col ? kHiddenScale : 0.0f;
  for (int row = 0; row < 3; ++row) h.m[4 * row + 3] = transform.m[4 * row + 3];
  if (!boundsWithinRange(bounds, h))
    for (int row = 0; row < 3; ++row) h.m[4 * row + 3] = 0.0f;
  return h;
}

Affine3x4 multiply(const Affine3x4& a, const Affine3x4& b) {
  Affine3x4 c;
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 4; ++col) {
      float sum = col == 3 ? a.m[4 * row + 3] : 0.0f;
      for (int k = 0; k < 3; ++k) sum += a.m[4 * row + k] * b.m[4 * k + col];
      c.m[4 * row + col] = sum;
    }
  return c;
}

}  // namespace

AnimationPlayer::AnimationPlayer(const Scene& scene) {
  meshBounds_.resize(scene.meshes.size());
  std::vector<bool> animated(scene.meshes.size());
  for (const AnimatedInstance& a : scene.animation.instances)
    if (a.instance < scene.instances.size() && scene.instances[a.instance].meshId < animated.size())
      animated[scene.instances[a.instance].meshId] = true;
  for (size_t m = 0; m < scene.meshes.size(); ++m)
    if (animated[m]) meshBounds_[m] = meshBounds(scene.meshes[m]);
}

size_t AnimationPlayer::pose(Scene& scene, int clip, float time) const {
  const std::vector<Affine3x4> world = nodeWorldTransforms(scene.animation, clip, time);
  size_t outOfRange = 0;
  for (const AnimatedInstance& a : scene.animation.instances) {
    Instance& instance = scene.instances[a.instance];
    const Bounds3& bounds = meshBounds_[instance.meshId];
    Affine3x4 transform = multiply(world[a.node], a.local);
    if (!usableTransform(transform)) {
      transform = hidden(transform, bounds);
    } else if (!boundsWithinRange(bounds, transform)) {
      transform = hidden(transform, bounds);
      ++outOfRange;
    }
    instance.objectToWorld = transform;
  }
  return outOfRange;
}

}  // namespace candela
