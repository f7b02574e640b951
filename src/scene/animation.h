#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "core/math.h"
#include "scene/mesh_deformation.h"

namespace candela {

// Node animation as glTF 2.0 defines it: keyframed translation, rotation and scale of the nodes above mesh
// instances, cameras and punctual lights, and keyframed morph target weights, sampled at a time in seconds. The
// instances of Scene::instances, the cameras of Scene::cameras and the lights of Scene::punctualLights that such
// nodes place are posed by posing the nodes, and skinned or morphed meshes are deformed (animation_player.h).

enum class AnimationInterpolation : uint8_t { Step, Linear, CubicSpline };
enum class AnimatedProperty : uint8_t { Translation, Rotation, Scale, Weights };

struct Scene;

// One property of one node over time.
struct AnimationChannel {
  uint32_t node = 0;  // in SceneAnimation::nodes
  AnimatedProperty property = AnimatedProperty::Translation;
  AnimationInterpolation interpolation = AnimationInterpolation::Linear;
  std::vector<float> times;  // seconds: finite and strictly increasing, at least one
  // Per key the value (x, y, z; a rotation is the unit quaternion x, y, z, w), or for CubicSpline three per key:
  // the in-tangent, the value and the out-tangent. Weights take weightCount numbers for each of these, four to a
  // Vec4 (the last one padded with zeros).
  std::vector<Vec4> values;
  uint32_t weightCount = 0;  // Weights: how many morph target weights

  // The Vec4s of one value (or tangent) of a Weights channel; 1 for the other properties.
  size_t vec4sPerValue() const { return property == AnimatedProperty::Weights ? (size_t(weightCount) + 3) / 4 : 1; }
};

// One of a file's animations (glTF's `animations` entries): channels meant to play together.
struct AnimationClip {
  std::string name;
  std::vector<AnimationChannel> channels;
  float start = 0.0f;  // the first and last key time over its channels
  float end = 0.0f;
};

// A node whose transform may change: an animated node or one below it. Its rest pose is its own transform.
struct AnimationNode {
  int32_t parent = -1;  // an earlier entry of SceneAnimation::nodes, or -1
  // Where parent is -1: the (fixed) world transform of the node's parent in the file, identity for a root.
  Affine3x4 parentToWorld;
  // The local transform: translation * rotation * scale, or, where `hasMatrix` (a node no channel targets that
  // gives a matrix, which need not decompose), `matrix`.
  Vec3 translation{0, 0, 0};
  Vec4 rotation{0, 0, 0, 1};
  Vec3 scale{1, 1, 1};
  uint32_t hasMatrix = 0;
  Affine3x4 matrix;
  uint32_t sourceIndex = 0;  // the node's index in the file, for messages
};

// An instance that an AnimationNode places.
struct AnimatedInstance {
  uint32_t instance = 0;  // in Scene::instances
  uint32_t node = 0;      // in SceneAnimation::nodes
  Affine3x4 local;        // applied before the node's world transform (EXT_mesh_gpu_instancing); else identity
};

// A camera that an AnimationNode carries, as glTF places one: at the node's origin, looking down its -Z with its
// +Y up.
struct AnimatedCamera {
  uint32_t camera = 0;  // in Scene::cameras
  uint32_t node = 0;    // in SceneAnimation::nodes
};

// A punctual light that an AnimationNode carries: at the node's origin, shining down its -Z.
struct AnimatedLight {
  uint32_t light = 0;  // in Scene::punctualLights
  uint32_t node = 0;   // in SceneAnimation::nodes
};

struct SceneAnimation {
  std::vector<AnimationNode> nodes;  // parents before their children
  std::vector<AnimatedInstance> instances;
  std::vector<AnimatedCamera> cameras;
  std::vector<AnimatedLight> lights;
  std::vector<Skin> skins;
  std::vector<MeshDeformation> deformations;  // one per skinned or morphed mesh
  std::vector<AnimationClip> clips;

  // Whether no clip animates anything.
  bool empty() const;
  // After instances were dropped or renumbered: `newIndex[i]` is instance i's new index, or ~0u where it went.
  void renumberInstances(const std::vector<uint32_t>& newIndex);
  // The same for punctual lights.
  void renumberLights(const std::vector<uint32_t>& newIndex);
  // The same for meshes; a deformation whose mesh went, or no longer has the vertex count it was made for
  // (`vertexCounts`, per mesh after the renumbering), is dropped. Returns how many were dropped that way.
  size_t renumberMeshes(const std::vector<uint32_t>& newIndex, const std::vector<size_t>& vertexCounts);
};

// Where a model's instances, cameras and punctual lights went when it was appended to a scene: the index of its
// first of each in the scene's arrays.
struct AppendedAt {
  uint32_t instance = 0;
  uint32_t camera = 0;
  uint32_t light = 0;
  uint32_t mesh = 0;
};

// Adds `part`, the animation of a model appended to a scene at `at` under `transform`, to `into`: its nodes,
// animated instances, cameras and lights, and its clips merged by index into those of `into` (clip i of every
// model plays as one).
void appendAnimation(SceneAnimation& into, const SceneAnimation& part, const Affine3x4& transform, AppendedAt at);

// The value of `channel` at `time` (seconds): before the first key the first value, after the last the last;
// rotations are unit quaternions (linear keys interpolated along the shorter arc, slerp). For Weights, the first
// four weights.
Vec4 sampleChannel(const AnimationChannel& channel, float time);
// The weightCount weights of a Weights channel at `time`, interpolated alike.
std::vector<float> sampleWeights(const AnimationChannel& channel, float time);

// The world transform of every node of `animation` when `clip` (an index into clips, or -1 for none: the rest
// pose) is at `time`.
std::vector<Affine3x4> nodeWorldTransforms(const SceneAnimation& animation, int clip, float time);

// Checks what backends and the player rely on in scene.animation (indices of nodes, instances, cameras, lights,
// meshes, skins and joints in range, parents before children, key times finite and increasing, value counts,
// deformation arrays that match their meshes, finite values); throws std::runtime_error naming the first problem.
void validateAnimation(const Scene& scene);

// The clip `choice` names (a clip's name or its index), or 0 when `choice` is empty; throws std::runtime_error
// listing the clips when none matches.
size_t findClip(const SceneAnimation& animation, const std::string& choice);

}  // namespace candela
