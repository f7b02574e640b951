#pragma once
#include <tiny_gltf.h>

#include <string>

#include "io/load_diagnostics.h"

namespace candela {

// Checks a glTF file's extension lists against what candela reads (gltf_loader.h, gltf_materials.h): an
// extensionsRequired entry it cannot honour stops the load with one line naming it (before any accessor is
// read, so a Draco-compressed file is not reported as broken data); an extensionsUsed entry it ignores is a
// warning naming it.
void checkGltfExtensions(const tinygltf::Model& model, const std::string& file, LoadWarnings& warnings);

// The same refusal from the JSON text, for a file that tinygltf could not parse: what an unsupported required
// extension stores (a Draco primitive's accessors without a bufferView) makes it fail with an unrelated message.
// Returns normally when the text names no such extension or is not readable JSON.
void refuseUnsupportedRequiredExtensions(const char* json, size_t size, const std::string& file);

// The index of the image a texture shows: EXT_texture_webp's `source` where the texture has one (the image its
// author preferred; `source` is then a PNG or JPEG fallback, or absent), else `source` (-1 when absent).
int textureImageIndex(const tinygltf::Texture& texture);

}  // namespace candela
