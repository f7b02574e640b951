#include "scene/animation_player.h"

#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "scene/scene_repair.h"
#include "scene/transform.h"

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

bool within(Vec3 v, float limit) {
  return std::fabs(v.x) <= limit && std::fabs(v.y) <= limit && std::fabs(v.z) <= limit;  // false for NaN
}

// The unit vector along v, or nothing where v has no usable length.
std::optional<Vec3> direction(Vec3 v) {
  const float l = length(v);
  if (!(l >= std::numeric_limits<float>::min()) || !std::isfinite(l)) return std::nullopt;
  return v / l;
}

// `rest` placed by `world` at the node's origin looking down its -Z with +Y up, as glTF places cameras; the
// target one unit ahead. Nothing where the transform leaves no usable frame (a node scaled to zero).
std::optional<CameraDescription> posedCamera(CameraDescription rest, const Affine3x4& world) {
  const Vec3 eye = world.point({0, 0, 0});
  const std::optional<Vec3> forward = direction(world.vector({0, 0, -1})), up = direction(world.vector({0, 1, 0}));
  if (!forward || !up || !within(eye, kMaxSceneCoordinate) || !(length(cross(*forward, *up)) > 1e-3f))
    return std::nullopt;
  rest.eye = eye;
  rest.target = eye + *forward;
  rest.up = *up;
  return rest;
}

}  // namespace

bool sceneCameraAnimated(const Scene& scene) {
  for (const AnimatedCamera& a : scene.animation.cameras)
    if (int64_t(a.camera) == scene.cameraIndex) return !scene.animation.empty();
  return false;
}

AnimationPlayer::AnimationPlayer(const Scene& scene) {
  for (const MeshDeformation& d : scene.animation.deformations) deformedMeshes_.push_back(d.mesh);
  std::sort(deformedMeshes_.begin(), deformedMeshes_.end());
  for (const AnimatedCamera& a : scene.animation.cameras) restCameras_.push_back(scene.cameras[a.camera].description);
  for (const AnimatedLight& a : scene.animation.lights) restLights_.push_back(scene.punctualLights[a.light]);
  meshBounds_.resize(scene.meshes.size());
  std::vector<bool> animated(scene.meshes.size());
  for (const AnimatedInstance& a : scene.animation.instances)
    if (a.instance < scene.instances.size() && scene.instances[a.instance].meshId < animated.size())
      animated[scene.instances[a.instance].meshId] = true;
  for (size_t m = 0; m < scene.meshes.size(); ++m)
    if (animated[m]) meshBounds_[m] = meshBounds(scene.meshes[m]);
}

void AnimationPlayer::deform(Scene& scene, int clip, float time, const std::vector<Affine3x4>& world) const {
  const SceneAnimation& animation = scene.animation;
  for (const MeshDeformation& d : animation.deformations) {
    std::vector<float> weights = d.weights;
    if (clip >= 0 && size_t(clip) < animation.clips.size())
      for (const AnimationChannel& channel : animation.clips[size_t(clip)].channels)
        if (channel.property == AnimatedProperty::Weights && channel.node == d.node) {
          const std::vector<float> sampled = sampleWeights(channel, time);
          std::copy_n(sampled.begin(), std::min(sampled.size(), weights.size()), weights.begin());
        }
    std::vector<Affine3x4> jointMatrices;
    Affine3x4 worldToNode;
    bool usable = true;
    if (d.skin >= 0) {
      const Skin& skin = animation.skins[size_t(d.skin)];
      for (size_t j = 0; j < skin.joints.size(); ++j)
        jointMatrices.push_back(multiply(world[skin.joints[j]], skin.inverseBinds[j]));
      usable = usableTransform(world[d.node]);
      if (usable) worldToNode = toAffine(glm::inverse(toMat4(world[d.node])));
    }
    Mesh& mesh = scene.meshes[d.mesh];
    if (!usable || !deformMesh(d, weights, jointMatrices, worldToNode, kMaxSceneCoordinate, mesh)) {
      mesh.positions = d.positions;  // the rest shape
      if (!mesh.normals.empty()) mesh.normals = d.normals;
      if (!mesh.tangents.empty()) mesh.tangents = d.tangents;
    }
  }
}

size_t AnimationPlayer::pose(Scene& scene, int clip, float time) const {
  const std::vector<Affine3x4> world = nodeWorldTransforms(scene.animation, clip, time);
  deform(scene, clip, time, world);
  std::vector<Bounds3> posedBounds = meshBounds_;
  for (uint32_t m : deformedMeshes_) posedBounds[m] = meshBounds(scene.meshes[m]);
  size_t outOfRange = 0;
  for (const AnimatedInstance& a : scene.animation.instances) {
    Instance& instance = scene.instances[a.instance];
    const Bounds3& bounds = posedBounds[instance.meshId];
    Affine3x4 transform = multiply(world[a.node], a.local);
    if (!usableTransform(transform)) {
      transform = hidden(transform, bounds);
    } else if (!boundsWithinRange(bounds, transform)) {
      transform = hidden(transform, bounds);
      ++outOfRange;
    }
    instance.objectToWorld = transform;
  }
  for (size_t c = 0; c < scene.animation.cameras.size(); ++c) {
    const AnimatedCamera& a = scene.animation.cameras[c];
    const CameraDescription posed = posedCamera(restCameras_[c], world[a.node]).value_or(restCameras_[c]);
    scene.cameras[a.camera].description = posed;
    if (int64_t(a.camera) == scene.cameraIndex) scene.camera = posed;
  }
  for (size_t l = 0; l < scene.animation.lights.size(); ++l) {
    const AnimatedLight& a = scene.animation.lights[l];
    PunctualLight light = restLights_[l];
    const Vec3 position = world[a.node].point({0, 0, 0});
    const std::optional<Vec3> shines = direction(world[a.node].vector({0, 0, -1}));
    if (shines && within(position, kMaxSceneCoordinate)) {
      light.position = position;
      light.direction = *shines;
    } else {
      light.intensity = {0, 0, 0};
    }
    scene.punctualLights[a.light] = light;
  }
  return outOfRange;
}

}  // namespace candela
