#pragma once
#include <string>
#include <string_view>

#include "io/load_diagnostics.h"
#include "io/path_confinement.h"
#include "scene/loaders/obj/obj_geometry_reader.h"
#include "scene/loaders/shared_model_assets.h"
#include "scene/scene.h"

namespace candela {

// Loads a Wavefront OBJ file, the MTL libraries it names (parsed by tinyobjloader) and their textures: the
// geometry is parsed in parallel (obj_geometry_reader.h), polygons are triangulated, relative (negative)
// references resolved, every object and group goes into one mesh with a material per triangle, and missing
// normals are generated (obj_mesh_builder.h). UVs follow the Mesh convention (v = 0 at the top of the image),
// so OBJ's v is flipped. A missing .mtl or texture is a warning, and so is one outside the OBJ file's folder
// unless `outside` allows it (path_confinement.h); malformed geometry throws LoadError naming the file and line.
// Only the materials that faces use are kept (in library order, then "default" for faces with none). With
// `shared`, material libraries come from and go to its cache and the materials' textures are left for
// shared->textures.finish() (shared_model_assets.h).
Scene loadObj(const std::string& path, LoadWarnings& warnings, OutsidePaths outside = OutsidePaths::Refused,
              SharedModelAssets* shared = nullptr);

// The same for OBJ text in memory, with no material libraries; `name` stands for the file in messages.
Scene loadObjText(const std::string& name, std::string_view text, LoadWarnings& warnings,
                  const ObjReadOptions& options = {});

}  // namespace candela
