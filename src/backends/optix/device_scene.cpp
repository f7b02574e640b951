#include "backends/optix/device_scene.h"

#include <stdexcept>
#include <string>

namespace candela::optix {

void DeviceScene::upload(const FlatScene& flat) {
  textures_ = DeviceTextures();
  textureViews_ = DeviceBuffer();
  view_ = flat.hostView();  // scalars and counts; every pointer is replaced below
  uploadArrays(flat, SceneArrayUpload::WithScene);
  uploadArrays(flat, SceneArrayUpload::WithMaterials);
  // Every texture with texels is sampled through a texture object, so the texel arrays stay on the host.
  textures_ = DeviceTextures(flat.textures, flat.texelBytes, flat.texelFloats);
  textureViews_ = DeviceBuffer::fromVector(textures_.views(), "texture descriptions");
  view_.texels.textures = textureViews_.as<const TextureView>();
  view_.texels.texelBytes = nullptr;
  view_.texels.texelFloats = nullptr;
  updateInstances(flat);
  updateEnvironment(flat);
}

void DeviceScene::uploadArrays(const FlatScene& flat, SceneArrayUpload when) {
  // The old copies go first, so that the new ones need no more device memory than they take.
#define CANDELA_RELEASE_DEVICE_ARRAY(Type, member, uploaded, count, description) \
  if (SceneArrayUpload::uploaded == when) member##_ = DeviceBuffer();
  CANDELA_SCENE_ARRAYS(CANDELA_RELEASE_DEVICE_ARRAY)
#undef CANDELA_RELEASE_DEVICE_ARRAY
#define CANDELA_UPLOAD_DEVICE_ARRAY(Type, member, uploaded, count, description)            \
  if (SceneArrayUpload::uploaded == when) {                                                \
    member##_ = DeviceBuffer::fromVector(flat.member, description);                        \
    view_.member = member##_.as<const Type>();                                             \
    setSceneArrayCount(view_, CANDELA_SCENE_ARRAY_COUNT_FIELD(count), flat.member.size()); \
  }
  CANDELA_SCENE_ARRAYS(CANDELA_UPLOAD_DEVICE_ARRAY)
#undef CANDELA_UPLOAD_DEVICE_ARRAY
}

void DeviceScene::updateInstances(const FlatScene& flat) {
  uploadArrays(flat, SceneArrayUpload::WithInstances);
  view_.inverseLightPower = flat.inverseLightPower;
  view_.environmentSelectProbability = flat.environmentSelectProbability;
  view_.directionalSelectProbability = flat.directionalSelectProbability;
  view_.boundedSelectProbability = flat.boundedSelectProbability;
  view_.boundedPunctualLightCount = flat.boundedPunctualLightCount;
}

void DeviceScene::updateMaterials(const FlatScene& flat) {
#define CANDELA_CHECK_DEVICE_ARRAY_SIZE(Type, member, uploaded, count, description) \
  if (SceneArrayUpload::uploaded == SceneArrayUpload::WithMaterials &&              \
      flat.member.size() * sizeof(Type) != member##_.size())                        \
    throw std::logic_error(std::string("DeviceScene::updateMaterials with a different number of ") + description);
  CANDELA_SCENE_ARRAYS(CANDELA_CHECK_DEVICE_ARRAY_SIZE)
#undef CANDELA_CHECK_DEVICE_ARRAY_SIZE
#define CANDELA_COPY_DEVICE_ARRAY_IN_PLACE(Type, member, uploaded, count, description) \
  if (SceneArrayUpload::uploaded == SceneArrayUpload::WithMaterials)                   \
    member##_.upload(flat.member.data(), member##_.size());
  CANDELA_SCENE_ARRAYS(CANDELA_COPY_DEVICE_ARRAY_IN_PLACE)
#undef CANDELA_COPY_DEVICE_ARRAY_IN_PLACE
  view_.hasCutouts = flat.hasCutouts ? 1u : 0u;
}

void DeviceScene::updateEnvironment(const FlatScene& flat) {
  environment_.clear();
  view_.environmentSelectProbability = flat.environmentSelectProbability;
  view_.directionalSelectProbability = flat.directionalSelectProbability;
  view_.boundedSelectProbability = flat.boundedSelectProbability;
  view_.environment = flat.environment;
  view_.environment.texels = copy(environment_, flat.environmentTexels, "the environment map");
  view_.environment.func = copy(environment_, flat.environmentDistribution.func, "the environment's sampling density");
  view_.environment.conditionalCdf =
      copy(environment_, flat.environmentDistribution.conditionalCdf, "the environment's rows");
  view_.environment.marginalCdf =
      copy(environment_, flat.environmentDistribution.marginalCdf, "the environment's columns");
  view_.environment.conditionalGuide =
      copy(environment_, flat.environmentDistribution.conditionalGuide, "the environment's row guides");
  view_.environment.marginalGuide =
      copy(environment_, flat.environmentDistribution.marginalGuide, "the environment's column guides");
}

size_t DeviceScene::deviceBytes() const {
  size_t total = textureViews_.size() + textures_.deviceBytes();
#define CANDELA_ADD_DEVICE_ARRAY_BYTES(Type, member, uploaded, count, description) total += member##_.size();
  CANDELA_SCENE_ARRAYS(CANDELA_ADD_DEVICE_ARRAY_BYTES)
#undef CANDELA_ADD_DEVICE_ARRAY_BYTES
  for (const DeviceBuffer& b : environment_) total += b.size();
  return total;
}

}  // namespace candela::optix
