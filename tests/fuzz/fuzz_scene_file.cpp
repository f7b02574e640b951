// libFuzzer entry point for JSON scene files. The loader reads the file by path, so each input is written to a
// private folder; the models it names are not read but stand in as one small triangle scene with a material
// named "paint" (from a .gltf name, with a camera too), so that transforms, material overrides, the model
// camera, the camera, environment and render settings are all reached. Any text must load or throw LoadError,
// never crash or hang, and give a valid scene.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "private_folder.h"
#include "scene/loaders/scene_file.h"

namespace {

candela::Scene standInModel(const std::string& path, candela::LoadWarnings&, candela::SharedModelAssets&) {
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
    candela::validateScene(scene);
  } catch (const candela::LoadError&) {
  }
  return 0;
}
