#pragma once
#include <functional>
#include <string>

#include "scene/loaders/load_diagnostics.h"
#include "scene/scene.h"

namespace candela {

// Loads a JSON scene file (docs/scene-file.md describes the format): models (.obj, .gltf, .glb) with transforms
// and material overrides, a camera (thin lens included), an environment and render settings. Paths are relative
// to the scene file. `loadModel` loads one model file (the caller decides about caching). Errors throw LoadError
// naming the file and the JSON path ("scene.json: models[1].transform.scale: expected a number or 3 numbers").
using ModelLoader = std::function<Scene(const std::string& path, LoadWarnings& warnings)>;
Scene loadSceneFile(const std::string& path, const ModelLoader& loadModel, LoadWarnings& warnings);

// Appends `part` to `scene` under `transform`: meshes, materials and textures are renumbered.
void appendScene(Scene& scene, Scene&& part, const Affine3x4& transform);

}  // namespace candela
