#pragma once
// A small animated glTF written for the animation tests.
#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "scene/scene_test_files.h"

namespace candela::test {

constexpr float kSqrtHalf = 0.70710678f;

// A glTF written for these tests: a unit quad (emissive, facing +z) under two nodes and a camera at z = 10, with
// two animations.
//   "Move": node 0 translates linearly (0,0,0) -> (2,0,0) -> (2,4,0) at 0, 1, 2 s and turns linearly from 0 to
//           90 degrees about z over 0..2 s; node 1 (the quad's, at rest at (0,1,0)) scales by step 1 -> 3 at 1 s.
//   "Bounce": node 1 translates by cubic spline from (0,1,0) (out-tangent (0,2,0)) to (0,1,0) over 0..1 s.
struct AnimatedFile {
  nlohmann::json gltf;
  std::vector<uint8_t> buffer;

  // Adds an accessor of float data and returns its index.
  int add(const std::vector<float>& values, const char* type) {
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

  AnimatedFile() {
    gltf = {{"asset", {{"version", "2.0"}}},
            {"bufferViews", nlohmann::json::array()},
            {"accessors", nlohmann::json::array()}};
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
    gltf["materials"] = {
        {{"emissiveFactor", {1, 1, 1}}, {"pbrMetallicRoughness", {{"baseColorFactor", {0, 0, 0, 1}}}}}};
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

  std::string write(const TempFolder& folder) {
    gltf["buffers"] = {{{"byteLength", buffer.size()}, {"uri", "animated.bin"}}};
    folder.write("animated.bin", std::string(buffer.begin(), buffer.end()));
    return folder.write("animated.gltf", gltf.dump());
  }
};

}  // namespace candela::test
