#include "support/animated_gltf.h"

#include <cstring>
#include <fstream>

namespace candela::test {

using nlohmann::json;

int AnimatedFile::add(const std::vector<float>& values, const char* type) {
  const size_t offset = buffer.size();
  buffer.resize(offset + values.size() * sizeof(float));
  std::memcpy(buffer.data() + offset, values.data(), values.size() * sizeof(float));
  const int components = std::string(type) == "SCALAR" ? 1 : std::string(type) == "VEC3" ? 3 : 4;
  gltf["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", values.size() * 4}});
  gltf["accessors"].push_back({{"bufferView", gltf["bufferViews"].size() - 1},
                               {"componentType", 5126},
                               {"count", values.size() / size_t(components)},
                               {"type", type}});
  return int(gltf["accessors"].size() - 1);
}

AnimatedFile::AnimatedFile() {
  gltf = {{"asset", {{"version", "2.0"}}}, {"bufferViews", json::array()}, {"accessors", json::array()}};
  const int positions = add({-0.5f, -0.5f, 0, 0.5f, -0.5f, 0, 0.5f, 0.5f, 0, -0.5f, 0.5f, 0}, "VEC3");
  const size_t indexOffset = buffer.size();
  const uint16_t indices[6] = {0, 1, 2, 0, 2, 3};
  buffer.resize(indexOffset + sizeof indices);
  std::memcpy(buffer.data() + indexOffset, indices, sizeof indices);
  gltf["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", indexOffset}, {"byteLength", sizeof indices}});
  gltf["accessors"].push_back(
      {{"bufferView", gltf["bufferViews"].size() - 1}, {"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}});
  const int indexAccessor = int(gltf["accessors"].size() - 1);
  gltf["meshes"] = {
      {{"primitives", {{{"attributes", {{"POSITION", positions}}}, {"indices", indexAccessor}, {"material", 0}}}}}};
  gltf["materials"] = {{{"emissiveFactor", {1, 1, 1}}, {"pbrMetallicRoughness", {{"baseColorFactor", {0, 0, 0, 1}}}}}};
  gltf["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.1}}}}};
  gltf["nodes"] = {{{"children", {1}}},
                   {{"mesh", 0}, {"translation", {0, 1, 0}}},
                   {{"camera", 0}, {"translation", {0, 0, 10}}}};
  gltf["scenes"] = {{{"nodes", {0, 2}}}};
  const int twoKeys = add({0, 2}, "SCALAR"), threeKeys = add({0, 1, 2}, "SCALAR"), unitKeys = add({0, 1}, "SCALAR");
  const int moves = add({0, 0, 0, 2, 0, 0, 2, 4, 0}, "VEC3");
  const int turns = add({0, 0, 0, 1, 0, 0, kSqrtHalf, kSqrtHalf}, "VEC4");
  const int scales = add({1, 1, 1, 3, 3, 3}, "VEC3");
  const int bounce = add({0, 0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0}, "VEC3");
  gltf["animations"] = {{{"name", "Move"},
                         {"samplers",
                          {{{"input", threeKeys}, {"output", moves}},
                           {{"input", twoKeys}, {"output", turns}, {"interpolation", "LINEAR"}},
                           {{"input", unitKeys}, {"output", scales}, {"interpolation", "STEP"}}}},
                         {"channels",
                          {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "translation"}}}},
                           {{"sampler", 1}, {"target", {{"node", 0}, {"path", "rotation"}}}},
                           {{"sampler", 2}, {"target", {{"node", 1}, {"path", "scale"}}}}}}},
                        {{"name", "Bounce"},
                         {"samplers", {{{"input", unitKeys}, {"output", bounce}, {"interpolation", "CUBICSPLINE"}}}},
                         {"channels", {{{"sampler", 0}, {"target", {{"node", 1}, {"path", "translation"}}}}}}}};
}

std::string AnimatedFile::write(const std::filesystem::path& folder) {
  gltf["buffers"] = {{{"byteLength", buffer.size()}, {"uri", "animated.bin"}}};
  std::ofstream(folder / "animated.bin", std::ios::binary)
      .write(reinterpret_cast<const char*>(buffer.data()), std::streamsize(buffer.size()));
  const std::filesystem::path path = folder / "animated.gltf";
  std::ofstream(path, std::ios::binary) << gltf.dump();
  return path.string();
}

}  // namespace candela::test
