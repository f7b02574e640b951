// write_animated_gltf FOLDER: writes the animated glTF of the tests (support/animated_gltf.h) into FOLDER, with a
// white backdrop behind the moving quad, which the quad lights: then every pixel's value depends on its samples,
// and a sample rendered twice or left out shows in a comparison of images.
#include <cstdio>
#include <filesystem>

#include "support/animated_gltf.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: write_animated_gltf FOLDER\n");
    return 2;
  }
  candela::test::AnimatedFile file;
  nlohmann::json& gltf = file.gltf;
  gltf["materials"].push_back(
      {{"pbrMetallicRoughness",
        {{"baseColorFactor", {0.8, 0.8, 0.8, 1}}, {"metallicFactor", 0}, {"roughnessFactor", 1}}}});
  nlohmann::json backdrop = gltf["meshes"][0]["primitives"][0];
  backdrop["material"] = gltf["materials"].size() - 1;
  gltf["meshes"].push_back({{"primitives", {backdrop}}});
  gltf["nodes"].push_back({{"mesh", gltf["meshes"].size() - 1}, {"translation", {0, 0, -1}}, {"scale", {12, 12, 1}}});
  gltf["scenes"][0]["nodes"].push_back(gltf["nodes"].size() - 1);
  std::filesystem::create_directories(argv[1]);
  std::printf("%s\n", file.write(argv[1]).c_str());
  return 0;
}
