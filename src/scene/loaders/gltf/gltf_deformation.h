#pragma once
#include <tiny_gltf.h>

#include <optional>
#include <string>
#include <vector>

#include "io/load_diagnostics.h"
#include "scene/loaders/gltf/gltf_accessors.h"
#include "scene/mesh_deformation.h"

namespace candela {

// Where a vertex of a converted glTF mesh came from: a primitive of the mesh and a vertex of its attributes.
struct GltfVertexOrigin {
  uint32_t primitive = 0;
  uint32_t vertex = 0;
};

// Reads into `deformation` (whose positions, normals and tangents are the converted mesh's, one per entry of
// `origins`) the morph targets of mesh `mesh` (POSITION deltas, and NORMAL and TANGENT deltas where the mesh has
// normals and tangents) and their weights at rest (node `node`'s, else the mesh's, else zeros). A primitive with
// another number of targets than the first, or target accessors of the wrong size, throw LoadError naming the
// file and the JSON path.
void readGltfMorphTargets(const tinygltf::Model& model, const GltfAccessorReader& accessors, int mesh, int node,
                          const std::vector<GltfVertexOrigin>& origins, const std::string& file,
                          MeshDeformation& deformation);

// Reads JOINTS_0 and WEIGHTS_0 of mesh `mesh`, and JOINTS_1 and WEIGHTS_1 where a primitive has them, into
// deformation.joints and jointWeights for skin `skin` of the file (four or eight per vertex, weights normalised
// to sum to one over all of them). Returns false, with a warning, where a primitive lacks JOINTS_0 or WEIGHTS_0
// (the mesh is then not skinned); a weighted joint beyond the skin's joints throws LoadError. More influences
// (JOINTS_2 and later) are ignored with a warning.
bool readGltfSkinWeights(const tinygltf::Model& model, const GltfAccessorReader& accessors, int mesh, int skin,
                         const std::vector<GltfVertexOrigin>& origins, const std::string& file, LoadWarnings& warnings,
                         MeshDeformation& deformation);

// Skin `skin` of the file with its joints as entries of SceneAnimation::nodes (`animationNodes` maps a file's
// node to one, or -1); nothing, with a warning, where a joint is not in the scene. Inverse bind matrices default
// to the identity; too few of them, or ones that are not finite, throw LoadError.
std::optional<Skin> readGltfSkin(const tinygltf::Model& model, const GltfAccessorReader& accessors, int skin,
                                 const std::vector<int32_t>& animationNodes, const std::string& file,
                                 LoadWarnings& warnings);

}  // namespace candela
