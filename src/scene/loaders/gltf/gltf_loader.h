#pragma once
#include <cstdint>
#include <string>

#include "io/load_diagnostics.h"
#include "io/path_confinement.h"
#include "scene/loaders/shared_model_assets.h"
#include "scene/scene.h"

namespace candela {

// Loads a glTF 2.0 file (.gltf with external or data-URI buffers and images, or binary .glb) through tinygltf.
// Each glTF mesh becomes one Mesh (its primitives' triangles with per-triangle materials) and every node that
// uses it an Instance with the node's world transform, so shared meshes are not copied. Under a mirroring
// transform (negative determinant) glTF keeps the object-space front, which is what kernel code does: the
// normal transform carries it. The first camera met in the node hierarchy becomes the scene's camera.
// KHR_lights_punctual lights become punctual lights placed by their nodes. Node animations, skins and morph targets
// become Scene::animation (animation.h); a skinned or morphed mesh is loaded posed at rest. Materials: see
// gltf_materials.h. Invalid input throws LoadError naming the file and the JSON path of the problem. External buffers
// and images must lie in the glTF file's folder unless `outside` allows others (path_confinement.h): a buffer elsewhere
// is an error, an image a warning. With `shared`, textures are left for shared->textures.finish()
// (shared_model_assets.h).
Scene loadGltf(const std::string& path, LoadWarnings& warnings, OutsidePaths outside = OutsidePaths::Refused,
               SharedModelAssets* shared = nullptr);

// The same for a .gltf or .glb held in memory; external buffers and images are not read. `name` stands for the
// file in messages.
Scene loadGltfBytes(const std::string& name, const uint8_t* data, size_t size, LoadWarnings& warnings);

}  // namespace candela
