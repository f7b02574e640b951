#include "backends/optix/device_scene.h"

#include <stdexcept>

namespace candela::optix {

void DeviceScene::upload(const FlatScene& flat) {
  buffers_.clear();
  textures_ = DeviceTextures();
  view_ = flat.hostView();  // scalars and counts; the pointers are replaced below, one line per array
  view_.positions = copy(buffers_, flat.positions, "vertex positions");
  view_.normals = copy(buffers_, flat.normals, "vertex normals");
  view_.uvs = copy(buffers_, flat.uvs, "texture coordinates");
  view_.tangents = copy(buffers_, flat.tangents, "vertex tangents");
  view_.colors = flat.colors.empty() ? nullptr : copy(buffers_, flat.colors, "vertex colours");
  view_.indices = copy(buffers_, flat.indices, "triangle indices");
  view_.triangleMaterials = copy(buffers_, flat.triangleMaterials, "triangle materials");
  view_.meshes = copy(buffers_, flat.meshes, "mesh records");
  materials_ = DeviceBuffer::fromVector(flat.materials, "materials");
  view_.materials = materials_.as<const Material>();
  // Every texture with texels is sampled through a texture object, so the texel arrays stay on the host.
  textures_ = DeviceTextures(flat.textures, flat.texelBytes, flat.texelFloats);
  view_.texels.textures = copy(buffers_, textures_.views(), "texture descriptions");
  view_.texels.texelBytes = nullptr;
  view_.texels.texelFloats = nullptr;
  updateInstances(flat);
  updateEnvironment(flat);
}

void DeviceScene::updateInstances(const FlatScene& flat) {
  posed_.clear();
  view_.instances = copy(posed_, flat.instances, "instance records");
  view_.lights = copy(posed_, flat.lights, "the light table");
  view_.lightCount = uint32_t(flat.lights.size());
  view_.lightCdf = copy(posed_, flat.lightCdf, "the light distribution");
  view_.inverseLightPower = flat.inverseLightPower;
  view_.lightBvh = copy(posed_, flat.lightBvh, "the light BVH");
  view_.lightBitTrails = copy(posed_, flat.lightBitTrails, "the light BVH's bit trails");
  view_.environmentSelectProbability = flat.environmentSelectProbability;
  view_.directionalSelectProbability = flat.directionalSelectProbability;
  view_.boundedSelectProbability = flat.boundedSelectProbability;
  view_.punctualLights = copy(posed_, flat.punctualLights, "the punctual lights");
  view_.punctualLightCount = uint32_t(flat.punctualLights.size());
  view_.boundedPunctualLightCount = flat.boundedPunctualLightCount;
}

void DeviceScene::updateMaterials(const FlatScene& flat) {
  if (flat.materials.size() * sizeof(Material) != materials_.size())
    throw std::logic_error("DeviceScene::updateMaterials with a different number of materials");
  materials_.upload(flat.materials.data(), materials_.size());
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
  size_t total = materials_.size() + textures_.deviceBytes();
  for (const DeviceBuffer& b : buffers_) total += b.size();
  for (const DeviceBuffer& b : environment_) total += b.size();
  for (const DeviceBuffer& b : posed_) total += b.size();
  return total;
}

}  // namespace candela::optix
