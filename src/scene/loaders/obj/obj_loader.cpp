#include "scene/loaders/obj/obj_loader.h"

#include <algorithm>
#include <filesystem>

#include "scene/loaders/obj/mtl_materials.h"
#include "scene/loaders/obj/obj_geometry_reader.h"
#include "scene/loaders/obj/obj_material_libraries.h"
#include "scene/loaders/obj/obj_mesh_builder.h"

namespace candela {

namespace {

namespace fs = std::filesystem;

// The geometry is parsed by candela's own reader (obj_geometry_reader.h) rather than tinyobjloader's LoadObj,
// which reads on one thread and holds its own copy of every attribute plus a 12-byte index triple per corner (and
// a vector per face) before the Scene is built: a 10M-triangle file took 25 s and peaked at 3.6 times the memory
// of the loaded scene (docs/performance.md). tinyobjloader still parses the material libraries.
Scene loadObjSource(const std::string& name, ObjTextSource& text, const std::optional<PathRule>& files,
                    LoadWarnings& warnings, const ObjReadOptions& options, SharedModelAssets* shared) {
  SharedModelAssets own;
  SharedModelAssets& assets = shared ? *shared : own;
  ObjMaterialLibraries libraries(name, files, assets.materialLibraries, warnings);
  ObjGeometry geometry = readObjGeometry(name, text, libraries, warnings, options);
  libraries.reportUnknownNames();

  Scene scene;
  scene.name = fs::path(name).stem().string();
  const uint32_t noMaterial = uint32_t(libraries.materials().size());
  scene.meshes.push_back(buildObjMesh(scene.name, std::move(geometry), noMaterial));
  // Only the materials that faces use are made (and so only their textures decoded): a scene's files often all
  // name one large library.
  std::vector<uint32_t> newId(size_t(noMaterial) + 1, UINT32_MAX);
  for (uint32_t id : scene.meshes[0].triangleMaterials) newId[id] = 0;
  for (uint32_t i = 0; i <= noMaterial; ++i) {
    if (newId[i] == UINT32_MAX) continue;
    newId[i] = uint32_t(scene.materials.size());
    if (i == noMaterial) {
      scene.materials.push_back(Material{});
      scene.materialNames.push_back("default");
      continue;
    }
    const tinyobj::material_t& mtl = libraries.materials()[i];
    const std::string& source = libraries.sourceOf(i);
    scene.materialNames.push_back(mtl.name);
    scene.materials.push_back(materialFromMtl(mtl, source, fs::path(source).parent_path().string(),
                                              files.value_or(PathRule{}), assets.textures, warnings));
  }
  for (uint32_t& id : scene.meshes[0].triangleMaterials) id = newId[id];
  scene.instances.push_back({0, Affine3x4{}});
  scene.inputFiles = libraries.libraryFiles();
  if (!shared) own.textures.finish(scene, 0, warnings);
  scene.cameraMissing = true;
  return scene;
}

}  // namespace

Scene loadObj(const std::string& path, LoadWarnings& warnings, OutsidePaths outside, SharedModelAssets* shared) {
  const ObjReadOptions options;
  std::unique_ptr<ObjTextSource> text = openObjTextFile(path, options.windowBytes);
  Scene scene = loadObjSource(path, *text, PathRule::forFile(path, outside), warnings, options, shared);
  scene.inputFiles.insert(scene.inputFiles.begin(), path);
  return scene;
}

Scene loadObjText(const std::string& name, std::string_view text, LoadWarnings& warnings,
                  const ObjReadOptions& options) {
  std::unique_ptr<ObjTextSource> source = objTextInMemory(text, options.windowBytes);
  return loadObjSource(name, *source, std::nullopt, warnings, options, nullptr);
}

}  // namespace candela
