#pragma once
#include "scene/loaders/obj/obj_material_libraries.h"
#include "scene/loaders/texture_table.h"

namespace candela {

// What the models of one load share, so that a scene of many files costs what its distinct content costs: each
// material library is parsed once, and each texture (by resolved path or embedding file, colour encoding and
// wrap modes) is decoded once and held once. Models loaded with it leave their texture fields pointing into
// `textures`; whoever assembles the scene calls textures.finish() once, over all their materials.
struct SharedModelAssets {
  MtlLibraryCache materialLibraries;
  TextureTable textures;
};

}  // namespace candela
