#include "scene/animation.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "scene/scene.h"
#include "scene/transform.h"

namespace candela {

namespace {

Vec4 operator+(Vec4 a, Vec4 b) { return {a.x + b.x, a.y + b.y, a.z + b.z, a.w + b.w}; }
Vec4 operator*(Vec4 a, float s) { return {a.x * s, a.y * s, a.z * s, a.w * s}; }
float dot4(Vec4 a, Vec4 b) { return a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w; }

// The unit quaternion along q, or the identity where q has no length.
Vec4 normalizedQuaternion(Vec4 q) {
  const float length = std::sqrt(dot4(q, q));
  return length > 0.0f && std::isfinite(length) ? q * (1.0f / length) : Vec4{0, 0, 0, 1};
}

// Spherical interpolation along the shorter arc; nearly equal rotations are interpolated linearly, where slerp's
// division by sin(angle) loses precision.
Vec4 slerp(Vec4 a, Vec4 b, float s) {
  float cosAngle = dot4(a, b);
  if (cosAngle < 0.0f) {
    b = b * -1.0f;
    cosAngle = -cosAngle;
  }
  if (cosAngle > 0.9995f) return normalizedQuaternion(a * (1.0f - s) + b * s);
  const float angle = std::acos(cosAngle), sinAngle = std::sin(angle);
  return normalizedQuaternion(a * (std::sin((1.0f - s) * angle) / sinAngle) + b * (std::sin(s * angle) / sinAngle));
}

glm::mat4 localMatrix(const AnimationNode& node, Vec3 t, Vec4 r, Vec3 s) {
  if (node.hasMatrix) return toMat4(node.matrix);
  return glm::translate(glm::mat4(1.0f), glm::vec3(t.x, t.y, t.z)) * glm::mat4_cast(glm::quat(r.w, r.x, r.y, r.z)) *
         glm::scale(glm::mat4(1.0f), glm::vec3(s.x, s.y, s.z));
}

bool finite(Vec4 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w); }

[[noreturn]] void fail(const std::string& what) { throw std::runtime_error(what); }

}  // namespace

bool SceneAnimation::empty() const {
  for (const AnimationClip& clip : clips)
    if (!clip.channels.empty()) return false;
  return true;
}

void SceneAnimation::renumberInstances(const std::vector<uint32_t>& newIndex) {
  size_t out = 0;
  for (const AnimatedInstance& a : instances) {
    if (a.instance >= newIndex.size() || newIndex[a.instance] == ~0u) continue;
    instances[out] = a;
    instances[out++].instance = newIndex[a.instance];
  }
  instances.resize(out);
}

void SceneAnimation::renumberLights(const std::vector<uint32_t>& newIndex) {
  size_t out = 0;
  for (const AnimatedLight& a : lights) {
    if (a.light >= newIndex.size() || newIndex[a.light] == ~0u) continue;
    lights[out] = a;
    lights[out++].light = newIndex[a.light];
  }
  lights.resize(out);
}

size_t SceneAnimation::renumberMeshes(const std::vector<uint32_t>& newIndex, const std::vector<size_t>& vertexCounts) {
  size_t out = 0, dropped = 0;
  for (size_t i = 0; i < deformations.size(); ++i) {
    MeshDeformation& d = deformations[i];
    const uint32_t mesh = d.mesh < newIndex.size() ? newIndex[d.mesh] : ~0u;
    if (mesh == ~0u) continue;  // its mesh went with all its triangles: nothing to deform
    if (mesh >= vertexCounts.size() || vertexCounts[mesh] != d.vertexCount()) {
      ++dropped;
      continue;
    }
    d.mesh = mesh;
    if (out != i) deformations[out] = std::move(d);  // a vector moved onto itself would be emptied
    ++out;
  }
  deformations.resize(out);
  return dropped;
}

void appendAnimation(SceneAnimation& into, const SceneAnimation& part, const Affine3x4& transform, AppendedAt at) {
  if (part.empty()) return;
  const uint32_t nodeBase = uint32_t(into.nodes.size());
  const glm::mat4 outer = toMat4(transform);
  for (AnimationNode node : part.nodes) {
    if (node.parent >= 0)
      node.parent += int32_t(nodeBase);
    else
      node.parentToWorld = toAffine(outer * toMat4(node.parentToWorld));
    into.nodes.push_back(node);
  }
  for (AnimatedInstance a : part.instances) {
    a.instance += at.instance;
    a.node += nodeBase;
    into.instances.push_back(a);
  }
  for (AnimatedCamera a : part.cameras) {
    a.camera += at.camera;
    a.node += nodeBase;
    into.cameras.push_back(a);
  }
  for (AnimatedLight a : part.lights) {
    a.light += at.light;
    a.node += nodeBase;
    into.lights.push_back(a);
  }
  const int32_t skinBase = int32_t(into.skins.size());
  for (Skin skin : part.skins) {
    for (uint32_t& joint : skin.joints) joint += nodeBase;
    into.skins.push_back(std::move(skin));
  }
  for (MeshDeformation d : part.deformations) {
    d.mesh += at.mesh;
    d.node += nodeBase;
    if (d.skin >= 0) d.skin += skinBase;
    into.deformations.push_back(std::move(d));
  }
  if (into.clips.size() < part.clips.size()) into.clips.resize(part.clips.size());
  for (size_t c = 0; c < part.clips.size(); ++c) {
    AnimationClip& clip = into.clips[c];
    const AnimationClip& added = part.clips[c];
    if (added.channels.empty()) continue;
    if (clip.name.empty()) clip.name = added.name;
    clip.start = clip.channels.empty() ? added.start : std::min(clip.start, added.start);
    clip.end = clip.channels.empty() ? added.end : std::max(clip.end, added.end);
    for (AnimationChannel channel : added.channels) {
      channel.node += nodeBase;
      clip.channels.push_back(std::move(channel));
    }
  }
}

namespace {

// Vec4 `part` (of vec4sPerValue()) of the channel's value at `time`.
Vec4 samplePart(const AnimationChannel& channel, float time, size_t part) {
  const std::vector<float>& times = channel.times;
  const bool cubic = channel.interpolation == AnimationInterpolation::CubicSpline;
  const bool rotation = channel.property == AnimatedProperty::Rotation;
  const size_t stride = channel.vec4sPerValue();
  auto element = [&](size_t e) { return channel.values[e * stride + part]; };
  auto value = [&](size_t key) { return element(cubic ? 3 * key + 1 : key); };
  auto finish = [&](Vec4 v) { return rotation ? normalizedQuaternion(v) : v; };
  if (!(time > times.front())) return finish(value(0));  // a NaN time too
  if (time >= times.back()) return finish(value(times.size() - 1));
  // times[k] <= time < times[k + 1]
  const size_t k = size_t(std::upper_bound(times.begin(), times.end(), time) - times.begin()) - 1;
  const float interval = times[k + 1] - times[k];
  const float s = (time - times[k]) / interval;
  switch (channel.interpolation) {
    case AnimationInterpolation::Step: return finish(value(k));
    case AnimationInterpolation::Linear:
      return rotation ? slerp(normalizedQuaternion(value(k)), normalizedQuaternion(value(k + 1)), s)
                      : value(k) * (1.0f - s) + value(k + 1) * s;
    case AnimationInterpolation::CubicSpline: {
      // glTF's cubic Hermite spline: the tangents are per second, so they scale with the key interval.
      const Vec4 outTangent = element(3 * k + 2) * interval;
      const Vec4 inTangent = element(3 * (k + 1)) * interval;
      const float s2 = s * s, s3 = s2 * s;
      return finish(value(k) * (2 * s3 - 3 * s2 + 1) + outTangent * (s3 - 2 * s2 + s) +
                    value(k + 1) * (-2 * s3 + 3 * s2) + inTangent * (s3 - s2));
    }
  }
  return finish(value(k));
}

}  // namespace

Vec4 sampleChannel(const AnimationChannel& channel, float time) { return samplePart(channel, time, 0); }

std::vector<float> sampleWeights(const AnimationChannel& channel, float time) {
  std::vector<float> weights(channel.weightCount);
  for (size_t part = 0; part < channel.vec4sPerValue(); ++part) {
    const Vec4 v = samplePart(channel, time, part);
    const float four[4] = {v.x, v.y, v.z, v.w};
    for (size_t i = 0; i < 4 && 4 * part + i < weights.size(); ++i) weights[4 * part + i] = four[i];
  }
  return weights;
}

std::vector<Affine3x4> nodeWorldTransforms(const SceneAnimation& animation, int clip, float time) {
  std::vector<Vec3> translations(animation.nodes.size()), scales(animation.nodes.size());
  std::vector<Vec4> rotations(animation.nodes.size());
  for (size_t n = 0; n < animation.nodes.size(); ++n) {
    translations[n] = animation.nodes[n].translation;
    rotations[n] = animation.nodes[n].rotation;
    scales[n] = animation.nodes[n].scale;
  }
  if (clip >= 0 && size_t(clip) < animation.clips.size())
    for (const AnimationChannel& channel : animation.clips[size_t(clip)].channels) {
      const Vec4 v = sampleChannel(channel, time);
      switch (channel.property) {
        case AnimatedProperty::Translation: translations[channel.node] = {v.x, v.y, v.z}; break;
        case AnimatedProperty::Rotation: rotations[channel.node] = v; break;
        case AnimatedProperty::Scale: scales[channel.node] = {v.x, v.y, v.z}; break;
        case AnimatedProperty::Weights: break;  // the player's (morph targets)
      }
    }
  std::vector<glm::mat4> world(animation.nodes.size());
  std::vector<Affine3x4> out(animation.nodes.size());
  for (size_t n = 0; n < animation.nodes.size(); ++n) {
    const AnimationNode& node = animation.nodes[n];
    const glm::mat4 parent = node.parent >= 0 ? world[size_t(node.parent)] : toMat4(node.parentToWorld);
    world[n] = parent * localMatrix(node, translations[n], rotations[n], scales[n]);
    out[n] = toAffine(world[n]);
  }
  return out;
}

namespace {

bool finite(Vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool finite(float x) { return std::isfinite(x); }

template <class T>
bool allFinite(const std::vector<T>& values) {
  return std::all_of(values.begin(), values.end(), [](const T& v) { return finite(v); });
}

void validateDeformations(const Scene& scene) {
  const SceneAnimation& animation = scene.animation;
  for (const Skin& skin : animation.skins) {
    if (skin.inverseBinds.size() != skin.joints.size()) fail("a skin has not one inverse bind matrix per joint");
    for (uint32_t joint : skin.joints)
      if (joint >= animation.nodes.size()) fail("a skin's joint is a missing node");
    for (const Affine3x4& m : skin.inverseBinds)
      for (float x : m.m)
        if (!std::isfinite(x)) fail("a skin has a non-finite inverse bind matrix");
  }
  for (const MeshDeformation& d : animation.deformations) {
    if (d.mesh >= scene.meshes.size() || d.node >= animation.nodes.size())
      fail("a mesh deformation refers to a missing mesh or node");
    const Mesh& mesh = scene.meshes[d.mesh];
    const size_t n = d.vertexCount(), targets = d.targetCount;
    if (n != mesh.positions.size() || d.normals.size() != mesh.normals.size() ||
        d.tangents.size() != mesh.tangents.size())
      fail("a mesh deformation does not match its mesh's vertices");
    if (d.positionDeltas.size() != targets * n || (!d.normalDeltas.empty() && d.normalDeltas.size() != targets * n) ||
        (!d.tangentDeltas.empty() && d.tangentDeltas.size() != targets * n) || d.weights.size() != targets)
      fail("a mesh deformation has the wrong number of morph target values");
    if (d.skin >= int32_t(animation.skins.size()) || d.skin < -1) fail("a mesh deformation refers to a missing skin");
    if (d.skin >= 0) {
      if ((d.influences != 4 && d.influences != 8) || d.joints.size() != d.influences * n ||
          d.jointWeights.size() != d.influences * n)
        fail("a mesh deformation has not four or eight joints and weights per vertex");
      for (uint32_t j : d.joints)
        if (j >= animation.skins[size_t(d.skin)].joints.size()) fail("a mesh deformation refers to a missing joint");
    } else if (!d.joints.empty() || !d.jointWeights.empty()) {
      fail("a mesh deformation has joints but no skin");
    }
    if (!allFinite(d.positions) || !allFinite(d.normals) || !allFinite(d.tangents) || !allFinite(d.positionDeltas) ||
        !allFinite(d.normalDeltas) || !allFinite(d.tangentDeltas) || !allFinite(d.jointWeights) ||
        !std::all_of(d.weights.begin(), d.weights.end(), [](float w) { return std::isfinite(w); }))
      fail("a mesh deformation has non-finite values");
  }
}

}  // namespace

void validateAnimation(const Scene& scene) {
  const SceneAnimation& animation = scene.animation;
  const size_t instanceCount = scene.instances.size(), cameraCount = scene.cameras.size(),
               lightCount = scene.punctualLights.size();
  for (size_t n = 0; n < animation.nodes.size(); ++n) {
    const AnimationNode& node = animation.nodes[n];
    if (node.parent < -1 || node.parent >= int32_t(n))
      fail("animation node " + std::to_string(n) + " has a parent that is missing or comes after it");
    const Vec4 t{node.translation.x, node.translation.y, node.translation.z, 0};
    const Vec4 s{node.scale.x, node.scale.y, node.scale.z, 0};
    bool matrixFinite = true, parentFinite = true;
    for (int i = 0; i < 12; ++i) {
      matrixFinite &= std::isfinite(node.matrix.m[i]);
      parentFinite &= std::isfinite(node.parentToWorld.m[i]);
    }
    if (!finite(t) || !finite(node.rotation) || !finite(s) || !matrixFinite || !parentFinite)
      fail("animation node " + std::to_string(n) + " has a non-finite transform");
  }
  for (const AnimatedInstance& a : animation.instances)
    if (a.instance >= instanceCount || a.node >= animation.nodes.size())
      fail("an animated instance refers to a missing instance or node");
  for (const AnimatedCamera& a : animation.cameras)
    if (a.camera >= cameraCount || a.node >= animation.nodes.size())
      fail("an animated camera refers to a missing camera or node");
  for (const AnimatedLight& a : animation.lights)
    if (a.light >= lightCount || a.node >= animation.nodes.size())
      fail("an animated light refers to a missing light or node");
  for (const AnimationClip& clip : animation.clips) {
    const std::string name = "animation '" + clip.name + "'";
    if (!std::isfinite(clip.start) || !std::isfinite(clip.end) || clip.start > clip.end)
      fail(name + " has a start or end that is not finite or out of order");
    for (const AnimationChannel& c : clip.channels) {
      if (c.node >= animation.nodes.size()) fail(name + " animates a missing node");
      if (uint8_t(c.interpolation) > uint8_t(AnimationInterpolation::CubicSpline) ||
          uint8_t(c.property) > uint8_t(AnimatedProperty::Weights))
        fail(name + " has an unknown interpolation or property");
      if (c.times.empty()) fail(name + " has a channel without keys");
      for (size_t k = 0; k < c.times.size(); ++k)
        if (!std::isfinite(c.times[k]) || (k > 0 && !(c.times[k] > c.times[k - 1])))
          fail(name + " has key times that are not finite and increasing");
      const size_t perKey = c.interpolation == AnimationInterpolation::CubicSpline ? 3 : 1;
      if ((c.property == AnimatedProperty::Weights) != (c.weightCount > 0) ||
          c.values.size() != perKey * c.times.size() * c.vec4sPerValue())
        fail(name + " has a channel with the wrong number of values");
      for (Vec4 v : c.values)
        if (!finite(v)) fail(name + " has non-finite key values");
    }
  }
  validateDeformations(scene);
}

size_t findClip(const SceneAnimation& animation, const std::string& choice) {
  if (choice.empty()) return 0;
  for (size_t i = 0; i < animation.clips.size(); ++i)
    if (animation.clips[i].name == choice || std::to_string(i) == choice) return i;
  std::string names;
  for (size_t i = 0; i < animation.clips.size(); ++i)
    names += (i ? ", " : "") + std::to_string(i) + " '" + animation.clips[i].name + "'";
  fail("no animation '" + choice + "' (animations: " + (names.empty() ? std::string("none") : names) + ")");
}

}  // namespace candela
