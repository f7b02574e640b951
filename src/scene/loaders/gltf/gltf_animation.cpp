#include "scene/loaders/gltf/gltf_animation.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace candela {

namespace {

std::optional<AnimatedProperty> propertyOf(const std::string& path) {
  if (path == "translation") return AnimatedProperty::Translation;
  if (path == "rotation") return AnimatedProperty::Rotation;
  if (path == "scale") return AnimatedProperty::Scale;
  if (path == "weights") return AnimatedProperty::Weights;
  return std::nullopt;
}

// Samplers are shared by channels; each is read once.
class SamplerReader {
 public:
  SamplerReader(const tinygltf::Model& model, const GltfAccessorReader& accessors, const std::string& file)
      : model_(model), accessors_(accessors), file_(file) {}

  // The keys of sampler `s` of animation `a` for `property` (`weightCount` weights for Weights), as a channel
  // without its node.
  AnimationChannel read(size_t a, int s, AnimatedProperty property, uint32_t weightCount,
                        const std::string& channelWhere) const {
    const tinygltf::Animation& animation = model_.animations[a];
    if (s < 0 || size_t(s) >= animation.samplers.size())
      failLoad(file_, channelWhere + ".sampler: sampler " + std::to_string(s) + " does not exist");
    const std::string where = "animations[" + std::to_string(a) + "].samplers[" + std::to_string(s) + "]";
    const tinygltf::AnimationSampler& sampler = animation.samplers[size_t(s)];
    AnimationChannel channel;
    channel.property = property;
    if (sampler.interpolation == "LINEAR")
      channel.interpolation = AnimationInterpolation::Linear;
    else if (sampler.interpolation == "STEP")
      channel.interpolation = AnimationInterpolation::Step;
    else if (sampler.interpolation == "CUBICSPLINE")
      channel.interpolation = AnimationInterpolation::CubicSpline;
    else
      failLoad(file_, where + ".interpolation: '" + sampler.interpolation + "' is not LINEAR, STEP or CUBICSPLINE");
    channel.times = readTimes(sampler.input, where + ".input");
    if (property == AnimatedProperty::Weights) {
      channel.weightCount = weightCount;
      channel.values = packedWeights(sampler.output, where + ".output", weightCount);
    } else if (property == AnimatedProperty::Rotation) {
      channel.values = accessors_.readVec4(sampler.output, where + ".output");
    } else {
      std::vector<Vec3> values = accessors_.readVec3(sampler.output, where + ".output");
      channel.values.reserve(values.size());
      for (Vec3 v : values) channel.values.push_back({v.x, v.y, v.z, 0.0f});
    }
    const bool cubic = channel.interpolation == AnimationInterpolation::CubicSpline;
    const size_t expected = channel.times.size() * (cubic ? 3 : 1) * channel.vec4sPerValue();
    if (channel.values.size() != expected) {
      const size_t perValue = property == AnimatedProperty::Weights ? weightCount : 1;
      failLoad(file_, where + ".output: " + std::to_string(channel.values.size() / channel.vec4sPerValue() * perValue) +
                          " values for " + std::to_string(channel.times.size()) + " key times (" +
                          sampler.interpolation + " needs " +
                          std::to_string(expected / channel.vec4sPerValue() * perValue) + ")");
    }
    for (size_t k = 0; k < channel.values.size(); ++k) {
      const Vec4 v = channel.values[k];
      if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z) || !std::isfinite(v.w))
        failLoad(file_, where + ".output: value " + std::to_string(k) + " is not finite");
    }
    return channel;
  }

 private:
  // Scalars, `count` to a value, packed four to a Vec4 (zeros after the last of each value). A count of
  // scalars that is no multiple of `count` leaves the last value out, which the caller's check of the number
  // of values names.
  std::vector<Vec4> packedWeights(int accessor, const std::string& where, uint32_t count) const {
    const std::vector<float> scalars = accessors_.readScalars(accessor, where);
    const size_t perValue = (size_t(count) + 3) / 4, values = scalars.size() / count;
    if (scalars.size() % count != 0) return {};
    std::vector<Vec4> packed(values * perValue, Vec4{0, 0, 0, 0});
    for (size_t v = 0; v < values; ++v)
      for (size_t i = 0; i < count; ++i) {
        Vec4& into = packed[v * perValue + i / 4];
        (i % 4 == 0 ? into.x : i % 4 == 1 ? into.y : i % 4 == 2 ? into.z : into.w) = scalars[v * count + i];
      }
    return packed;
  }

  std::vector<float> readTimes(int accessor, const std::string& where) const {
    std::vector<float> times = accessors_.readScalars(accessor, where);
    if (times.empty()) failLoad(file_, where + ": an animation sampler needs at least one key");
    for (size_t k = 0; k < times.size(); ++k) {
      if (!std::isfinite(times[k]))
        failLoad(file_, where + ": key time " + std::to_string(k) + " is not a finite number");
      if (k > 0 && !(times[k] > times[k - 1]))
        failLoad(file_, where + ": key times must increase, but key " + std::to_string(k) + " (" +
                            std::to_string(times[k]) + " s) follows " + std::to_string(times[k - 1]) + " s");
    }
    return times;
  }

  const tinygltf::Model& model_;
  const GltfAccessorReader& accessors_;
  const std::string& file_;
};

}  // namespace

uint32_t morphTargetCount(const tinygltf::Model& model, int node) {
  if (node < 0 || size_t(node) >= model.nodes.size()) return 0;
  const int mesh = model.nodes[size_t(node)].mesh;
  if (mesh < 0 || size_t(mesh) >= model.meshes.size() || model.meshes[size_t(mesh)].primitives.empty()) return 0;
  return uint32_t(model.meshes[size_t(mesh)].primitives[0].targets.size());
}

std::vector<bool> animatedGltfNodes(const tinygltf::Model& model) {
  std::vector<bool> animated(model.nodes.size());
  for (const tinygltf::Animation& animation : model.animations)
    for (const tinygltf::AnimationChannel& channel : animation.channels)
      if (channel.target_node >= 0 && size_t(channel.target_node) < animated.size() &&
          propertyOf(channel.target_path) && channel.target_path != "weights")
        animated[size_t(channel.target_node)] = true;
  return animated;
}

std::vector<AnimationClip> readGltfAnimations(const tinygltf::Model& model, const GltfAccessorReader& accessors,
                                              const std::vector<int32_t>& animationNodes, const std::string& file,
                                              LoadWarnings& warnings) {
  SamplerReader samplers(model, accessors, file);
  std::vector<AnimationClip> clips;
  size_t weightChannelsWithoutTargets = 0, unknownChannels = 0;
  std::string unknownPath;  // the first
  for (size_t a = 0; a < model.animations.size(); ++a) {
    const tinygltf::Animation& animation = model.animations[a];
    AnimationClip clip;
    clip.name = animation.name.empty() ? "animations[" + std::to_string(a) + "]" : animation.name;
    for (size_t c = 0; c < animation.channels.size(); ++c) {
      const tinygltf::AnimationChannel& source = animation.channels[c];
      const std::string where = "animations[" + std::to_string(a) + "].channels[" + std::to_string(c) + "]";
      if (source.target_node < 0) continue;  // a channel an extension targets elsewhere
      if (size_t(source.target_node) >= model.nodes.size())
        failLoad(file, where + ".target.node: node " + std::to_string(source.target_node) + " does not exist");
      const std::optional<AnimatedProperty> property = propertyOf(source.target_path);
      if (!property) {
        if (unknownChannels++ == 0) unknownPath = source.target_path;
        continue;
      }
      const int32_t node = animationNodes[size_t(source.target_node)];
      if (node < 0) continue;  // outside the scene
      const uint32_t targets = *property == AnimatedProperty::Weights ? morphTargetCount(model, source.target_node) : 0;
      if (*property == AnimatedProperty::Weights && targets == 0) {
        ++weightChannelsWithoutTargets;
        continue;
      }
      AnimationChannel channel = samplers.read(a, source.sampler, *property, targets, where);
      channel.node = uint32_t(node);
      clip.start = clip.channels.empty() ? channel.times.front() : std::min(clip.start, channel.times.front());
      clip.end = clip.channels.empty() ? channel.times.back() : std::max(clip.end, channel.times.back());
      clip.channels.push_back(std::move(channel));
    }
    clips.push_back(std::move(clip));
  }
  if (weightChannelsWithoutTargets > 0)
    warnings.add(file,
                 std::to_string(weightChannelsWithoutTargets) +
                     " animation channels of morph target weights are ignored: their nodes have no morph targets");
  if (unknownChannels > 0)
    warnings.add(file, std::to_string(unknownChannels) +
                           " animation channels of paths glTF does not define (such as '" + unknownPath +
                           "') are ignored");
  return clips;
}

}  // namespace candela
