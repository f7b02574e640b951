#pragma once
#include <cstdint>
#include <vector>

#include "core/math.h"

namespace candela {

struct Mesh;

// A skin as glTF defines it: the nodes that act as its joints and, per joint, the inverse bind matrix that takes
// the mesh from its bind pose into the joint's space.
struct Skin {
  std::vector<uint32_t> joints;         // in SceneAnimation::nodes
  std::vector<Affine3x4> inverseBinds;  // one per joint
};

// A mesh whose vertices an animation moves, as glTF 2.0 defines it: first its morph targets, blended by weights
// (the node's, which a channel may animate), then linear blend skinning by up to eight joints per vertex. The mesh
// belongs to one node (the loader gives such a node a mesh of its own) and stays in that node's space: a skinned
// vertex goes to the world through the joints and comes back through the inverse of the node's world transform, so
// that the instance keeps the node's transform and whatever places the model (a scene file's transform) applies
// once.
struct MeshDeformation {
  uint32_t mesh = 0;  // in Scene::meshes
  uint32_t node = 0;  // in SceneAnimation::nodes: the node that places the mesh, and whose weights channels apply
  // The base shape, as the file gives it.
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;   // empty where the mesh has none
  std::vector<Vec4> tangents;  // empty where the mesh has none
  // Morph targets: per target a position delta for every vertex, target after target; normal and tangent deltas
  // likewise, or none (tangent deltas move a tangent's direction; its handedness w stays). `weights` are the
  // targets' weights at rest.
  uint32_t targetCount = 0;
  std::vector<Vec3> positionDeltas;
  std::vector<Vec3> normalDeltas;
  std::vector<Vec3> tangentDeltas;
  std::vector<float> weights;
  // Skinning, where skin >= 0: per vertex `influences` (4 or 8: glTF's JOINTS_0, and JOINTS_1 where the mesh has
  // it) indices into the skin's joints and as many weights, vertex after vertex.
  int32_t skin = -1;  // in SceneAnimation::skins
  uint32_t influences = 4;
  std::vector<uint32_t> joints;
  std::vector<float> jointWeights;

  size_t vertexCount() const { return positions.size(); }
};

// Writes the deformed vertices (positions, normals and tangents, each where the mesh has them) into `mesh`, whose
// vertex count must be deformation.vertexCount(): the morph targets blended with `weights` (one per target), then
// skinned with `jointMatrices` (one per joint of the skin: the joint's world transform times its inverse bind
// matrix) and brought into the node's space by `worldToNode`. Normals and tangents are transformed by the blended
// matrix's inverse transpose and its linear part, and normalised (zero where they vanish). Returns false, changing
// nothing, where a deformed position is not finite or lies beyond `maxCoordinate`.
bool deformMesh(const MeshDeformation& deformation, const std::vector<float>& weights,
                const std::vector<Affine3x4>& jointMatrices, const Affine3x4& worldToNode, float maxCoordinate,
                Mesh& mesh);

}  // namespace candela
