#include "backends/optix/device_scene.h"

namespace candela::optix {

void DeviceScene::upload(const FlatScene& flat) {
  buffers_.clear();
  textures_ = DeviceTextures();
  view_ = flat.hostView();  // scalars and counts; the pointers are replaced below, one line per array
  view_.positions = copy(flat.positions, "vertex positions");
  view_.normals = copy(flat.normals, "vertex normals");
  view_.uvs = copy(flat.uvs, "texture coordinates");
  view_.tangents = copy(flat.tangents, "vertex tangents");
  view_.indices = copy(flat.indices, "triangle indices");
  view_.triangleMaterials = copy(flat.triangleMaterials, "triangle materials");
  view_.meshes = copy(flat.meshes, "mesh records");
  view_.instances = copy(flat.instances, "instance records");
  view_.materials = copy(flat.materials, "materials");
  // Every texture with texels is sampled through a texture object, so the texel arrays stay on the host.
  textures_ = DeviceTextures(flat.textures, flat.texelBytes, flat.texelFloats);
  view_.texels.textures = copy(textures_.views(), "texture descriptions");
  view_.texels.texelBytes = nullptr;
  view_.texels.texelFloats = nullptr;
  view_.lights = copy(flat.lights, "the light table");
  view_.lightCdf = copy(flat.lightCdf, "the light distribution");
  view_.environment.texels = copy(flat.environmentTexels, "the environment map");
  view_.environment.func = copy(flat.environmentDistribution.func, "the environment's sampling density");
  view_.environment.conditionalCdf = copy(flat.environmentDistribution.conditionalCdf, "the environment's rows");
  view_.environment.marginalCdf = copy(flat.environmentDistribution.marginalCdf, "the environment's columns");
}

size_t DeviceScene::deviceBytes() const {
  size_t total = 0;
  for (const DeviceBuffer& b : buffers_) total += b.size();
  return total + textures_.deviceBytes();
}

}  // namespace candela::optix
