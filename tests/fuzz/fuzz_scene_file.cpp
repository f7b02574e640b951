// libFuzzer entry point for JSON scene files. The loader reads the file by path, so each input is written to a
// private folder; the models it names are not read but stand in as one small triangle scene with a material
// named "paint" (from a .gltf name, with a camera too), so that transforms, material overrides, the model
// camera, the camera, environment and render settings are all reached. A .glb name stands for an animated glTF
// (the gltf seed skinned_morphed_animated.gltf: a skinned and a morphed mesh, an animated camera and light), so
// that placing models' animations, cameras and lights, and placing a deformed model again, are reached too. Any
// text must load or throw LoadError, never crash or hang, and give a scene that the repair every load ends with
// makes valid, and whose animation then poses validly (posed_clips.h).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <iterator>
#include <string>
#include <string_view>

#include "posed_clips.h"
#include "private_folder.h"
#include "scene/loaders/gltf/gltf_loader.h"
#include "scene/loaders/scene_file.h"
#include "scene/scene_repair.h"

namespace {

// Loaded once: CANDELA_FUZZ_ANIMATED_MODEL is the seed's path in the source tree.
const candela::Scene& animatedModel() {
  static const candela::Scene model = [] {
    try {
      std::ifstream in(CANDELA_FUZZ_ANIMATED_MODEL, std::ios::binary);
      const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
      candela::LoadWarnings ignored;
      return candela::loadGltfBytes(CANDELA_FUZZ_ANIMATED_MODEL, reinterpret_cast<const uint8_t*>(bytes.data()),
                                    bytes.size(), ignored);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "fuzz_scene_file: the animated stand-in model does not load: %s\n", e.what());
      std::abort();
    }
  }();
  return model;
}

candela::Scene standInModel(const std::string& path, candela::LoadWarnings&, candela::SharedModelAssets&) {
  if (path.size() >= 4 && path.compare(path.size() - 4, 4, ".glb") == 0) {
    candela::Scene s = animatedModel();
    s.inputFiles = {path};
    return s;
  }
  candela::Scene s;
  s.name = "stand-in";
  candela::Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.indices = {0, 1, 2};
  m.triangleMaterials = {0};
  s.meshes.push_back(m);
  s.instances.push_back({0, candela::Affine3x4{}});
  s.materials.push_back(candela::Material{});
  s.materialNames.push_back("paint");
  s.cameraMissing = path.size() < 5 || path.compare(path.size() - 5, 5, ".gltf") != 0;
  if (!s.cameraMissing) s.camera = {{0, 0, 3}, {0, 0, 0}, {0, 1, 0}, 50.0f, 0.0f, 0.0f};
  s.inputFiles.push_back(path);
  return s;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = candela::fuzz::writePrivateFile("scene.json", {reinterpret_cast<const char*>(data), size});
  candela::LoadWarnings warnings;
  try {
    candela::Scene scene = candela::loadSceneFile(path, standInModel, warnings);
    candela::repairScene(scene, path, warnings);  // as every load does (app/scene_loading.cpp); ends with validateScene
    candela::fuzz::poseClips(scene);
  } catch (const candela::LoadError&) {
  }
  return 0;
}
