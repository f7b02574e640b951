#include "scene/cache/scene_serialization.h"

#include <type_traits>

#include "kernel/scene_arrays.h"

namespace candela {

namespace {

// The per-mesh arrays of kernel/scene_arrays.h, which a mesh's record holds after its name, are Mesh's members.
#define CANDELA_CHECK_MESH_MEMBER(Type, member, upload, count, description) \
  static_assert(std::is_same_v<decltype(Mesh::member), std::vector<Type>>,  \
                "Mesh::" #member " must be the std::vector<" #Type "> that kernel/scene_arrays.h lists");
CANDELA_MESH_ARRAYS(CANDELA_CHECK_MESH_MEMBER)
#undef CANDELA_CHECK_MESH_MEMBER

static_assert(std::is_trivially_copyable_v<Material> && std::is_trivially_copyable_v<Instance> &&
              std::is_trivially_copyable_v<CameraDescription> && std::is_trivially_copyable_v<AnimationNode> &&
              std::is_trivially_copyable_v<AnimatedInstance> && std::is_trivially_copyable_v<AnimatedCamera> &&
              std::is_trivially_copyable_v<AnimatedLight> && std::is_trivially_copyable_v<Medium> &&
              std::is_trivially_copyable_v<MediumGrid>);

void writeTexture(BinaryWriter& out, const Texture& t) {
  out.string(t.name);
  out.value(t.width);
  out.value(t.height);
  out.value(t.channels);
  out.value(uint8_t(t.srgb));
  out.value(t.wrapU);
  out.value(t.wrapV);
  out.array(t.bytes);
  out.array(t.floats);
}

void readTexture(BinaryReader& in, Texture& t) {
  uint8_t srgb = 0;
  in.string(t.name);
  in.value(t.width);
  in.value(t.height);
  in.value(t.channels);
  in.value(srgb);
  in.value(t.wrapU);
  in.value(t.wrapV);
  in.array(t.bytes);
  in.array(t.floats);
  t.srgb = srgb != 0;
}

template <class T>
void writeOptional(BinaryWriter& out, const std::optional<T>& v) {
  out.value(uint8_t(v.has_value()));
  if (v) out.value(*v);
}

template <class T>
void readOptional(BinaryReader& in, std::optional<T>& v) {
  uint8_t present = 0;
  in.value(present);
  v.reset();
  if (present) {
    T x{};
    in.value(x);
    v = x;
  }
}

// The least a mesh, a texture, a string, an animation clip, channel, skin or mesh deformation takes in the file,
// for checking counts before allocating.
constexpr uint64_t kMeshBytes = (1 CANDELA_MESH_ARRAYS(CANDELA_SCENE_ARRAY_ONE)) * sizeof(uint64_t);
constexpr uint64_t kTextureBytes = 3 * sizeof(uint64_t);
constexpr uint64_t kStringBytes = sizeof(uint64_t);
constexpr uint64_t kClipBytes = 2 * sizeof(uint64_t) + 2 * sizeof(float);
constexpr uint64_t kChannelBytes = 2 * sizeof(uint32_t) + 2 + 2 * sizeof(uint64_t);
constexpr uint64_t kSkinBytes = 2 * sizeof(uint64_t);
constexpr uint64_t kDeformationBytes = 5 * sizeof(uint32_t) + 9 * sizeof(uint64_t);

void writeAnimation(BinaryWriter& out, const SceneAnimation& a) {
  out.array(a.nodes);
  out.array(a.instances);
  out.array(a.cameras);
  out.array(a.lights);
  out.value(uint64_t(a.skins.size()));
  for (const Skin& s : a.skins) {
    out.array(s.joints);
    out.array(s.inverseBinds);
  }
  out.value(uint64_t(a.deformations.size()));
  for (const MeshDeformation& d : a.deformations) {
    out.value(d.mesh);
    out.value(d.node);
    out.array(d.positions);
    out.array(d.normals);
    out.array(d.tangents);
    out.value(d.targetCount);
    out.array(d.positionDeltas);
    out.array(d.normalDeltas);
    out.array(d.tangentDeltas);
    out.array(d.weights);
    out.value(d.skin);
    out.value(d.influences);
    out.array(d.joints);
    out.array(d.jointWeights);
  }
  out.value(uint64_t(a.clips.size()));
  for (const AnimationClip& clip : a.clips) {
    out.string(clip.name);
    out.value(clip.start);
    out.value(clip.end);
    out.value(uint64_t(clip.channels.size()));
    for (const AnimationChannel& c : clip.channels) {
      out.value(c.node);
      out.value(c.property);
      out.value(c.interpolation);
      out.value(c.weightCount);
      out.array(c.times);
      out.array(c.values);
    }
  }
}

void readAnimation(BinaryReader& in, SceneAnimation& a) {
  in.array(a.nodes);
  in.array(a.instances);
  in.array(a.cameras);
  in.array(a.lights);
  a.skins.resize(size_t(in.count(kSkinBytes)));
  for (Skin& s : a.skins) {
    in.array(s.joints);
    in.array(s.inverseBinds);
  }
  a.deformations.resize(size_t(in.count(kDeformationBytes)));
  for (MeshDeformation& d : a.deformations) {
    in.value(d.mesh);
    in.value(d.node);
    in.array(d.positions);
    in.array(d.normals);
    in.array(d.tangents);
    in.value(d.targetCount);
    in.array(d.positionDeltas);
    in.array(d.normalDeltas);
    in.array(d.tangentDeltas);
    in.array(d.weights);
    in.value(d.skin);
    in.value(d.influences);
    in.array(d.joints);
    in.array(d.jointWeights);
  }
  a.clips.resize(size_t(in.count(kClipBytes)));
  for (AnimationClip& clip : a.clips) {
    in.string(clip.name);
    in.value(clip.start);
    in.value(clip.end);
    clip.channels.resize(size_t(in.count(kChannelBytes)));
    for (AnimationChannel& c : clip.channels) {
      in.value(c.node);
      in.value(c.property);
      in.value(c.interpolation);
      in.value(c.weightCount);
      in.array(c.times);
      in.array(c.values);
    }
  }
}

}  // namespace

void writeScene(BinaryWriter& out, const Scene& s) {
  out.string(s.name);
  out.value(uint64_t(s.meshes.size()));
  for (const Mesh& m : s.meshes) {
    out.string(m.name);
#define CANDELA_WRITE_MESH_ARRAY(Type, member, upload, count, description) out.array(m.member);
    CANDELA_MESH_ARRAYS(CANDELA_WRITE_MESH_ARRAY)
#undef CANDELA_WRITE_MESH_ARRAY
  }
  out.array(s.instances);
  out.array(s.materials);
  out.value(uint64_t(s.materialNames.size()));
  for (const std::string& n : s.materialNames) out.string(n);
  out.value(uint64_t(s.textures.size()));
  for (const Texture& t : s.textures) writeTexture(out, t);
  out.value(s.environment.radiance);
  writeTexture(out, s.environment.map);
  out.value(s.environment.intensity);
  out.value(s.environment.rotationDegrees);
  out.value(uint8_t(s.environment.visibleToCamera));
  out.array(s.punctualLights);
  out.array(s.media);
  out.array(s.mediumGrids);
  out.array(s.mediumGridValues);
  out.value(s.camera);
  out.value(s.cameraMedium);
  writeOptional(out, s.renderHints.width);
  writeOptional(out, s.renderHints.height);
  writeOptional(out, s.renderHints.samplesPerPixel);
  writeOptional(out, s.renderHints.maxDepth);
  out.value(uint8_t(s.cameraMissing));
  out.value(uint64_t(s.cameras.size()));
  for (const NamedCamera& c : s.cameras) {
    out.string(c.name);
    out.value(c.description);
  }
  out.value(s.cameraIndex);
  out.value(uint64_t(s.inputFiles.size()));
  for (const std::string& f : s.inputFiles) out.string(f);
  writeAnimation(out, s.animation);
}

bool readScene(BinaryReader& in, Scene& s) {
  in.string(s.name);
  s.meshes.resize(size_t(in.count(kMeshBytes)));
  for (Mesh& m : s.meshes) {
    in.string(m.name);
#define CANDELA_READ_MESH_ARRAY(Type, member, upload, count, description) in.array(m.member);
    CANDELA_MESH_ARRAYS(CANDELA_READ_MESH_ARRAY)
#undef CANDELA_READ_MESH_ARRAY
  }
  in.array(s.instances);
  in.array(s.materials);
  s.materialNames.resize(size_t(in.count(kStringBytes)));
  for (std::string& n : s.materialNames) in.string(n);
  s.textures.resize(size_t(in.count(kTextureBytes)));
  for (Texture& t : s.textures) readTexture(in, t);
  uint8_t flag = 0;
  in.value(s.environment.radiance);
  readTexture(in, s.environment.map);
  in.value(s.environment.intensity);
  in.value(s.environment.rotationDegrees);
  in.value(flag);
  s.environment.visibleToCamera = flag != 0;
  in.array(s.punctualLights);
  in.array(s.media);
  in.array(s.mediumGrids);
  in.array(s.mediumGridValues);
  in.value(s.camera);
  in.value(s.cameraMedium);
  readOptional(in, s.renderHints.width);
  readOptional(in, s.renderHints.height);
  readOptional(in, s.renderHints.samplesPerPixel);
  readOptional(in, s.renderHints.maxDepth);
  in.value(flag);
  s.cameraMissing = flag != 0;
  s.cameras.resize(size_t(in.count(kStringBytes + sizeof(CameraDescription))));
  for (NamedCamera& c : s.cameras) {
    in.string(c.name);
    in.value(c.description);
  }
  in.value(s.cameraIndex);
  s.inputFiles.resize(size_t(in.count(kStringBytes)));
  for (std::string& f : s.inputFiles) in.string(f);
  readAnimation(in, s.animation);
  return in.ok();
}

}  // namespace candela
