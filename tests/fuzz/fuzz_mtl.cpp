// libFuzzer entry point for material libraries as OBJ files read them: tinyobjloader's MTL reader, then the
// mapping of every material onto candela's models and the decoding of the textures they name (relative names
// resolve in an empty private folder, so they are missing: a warning each). Any text must load or throw
// LoadError, never crash or hang, and give a valid scene.
#include <tiny_obj_loader.h>

#include <cstddef>
#include <cstdint>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "private_folder.h"
#include "scene/loaders/obj/mtl_materials.h"
#include "scene/loaders/texture_table.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::istringstream text(std::string(reinterpret_cast<const char*>(data), size));
  std::map<std::string, int> index;
  std::vector<tinyobj::material_t> materials;
  std::string mtlWarnings, mtlErrors;
  tinyobj::LoadMtl(&index, &materials, &text, &mtlWarnings, &mtlErrors);
  candela::LoadWarnings warnings;
  try {
    candela::Scene scene;
    candela::TextureTable textures;
    const std::string folder = candela::fuzz::privateFolder().string();
    const candela::PathRule files{folder, candela::OutsidePaths::Refused};
    for (const tinyobj::material_t& m : materials)
      scene.materials.push_back(candela::materialFromMtl(m, "fuzz.mtl", folder, files, textures, warnings));
    textures.finish(scene, 0, warnings);
    candela::validateScene(scene);
  } catch (const candela::LoadError&) {
  }
  return 0;
}
