#pragma once
#include <string>
#include <vector>

#include "backends/cpu/embree.h"
#include "scene/flat_scene.h"

namespace candela {

// Embree's view of a scene: one triangle geometry per mesh, each in its own scene, instanced into a top-level
// scene with the instance transforms. Instance and primitive ids match SceneView's. Meshes with a material that
// can let rays through carry the pass-through filter functions (embree_pass_through.h); the others none.
class EmbreeScene {
 public:
  EmbreeScene();
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  void build(const FlatScene& flat);
  // After FlatScene::replaceInstanceTransforms: the instances take their new transforms and only the top-level
  // BVH is built again.
  void updateInstanceTransforms(const FlatScene& flat);
  // After FlatScene::replaceMeshVertices: the meshes `deformed` take their new positions and their BVHs are
  // built again; call updateInstanceTransforms afterwards, which commits the top level again.
  void updateMeshVertices(const FlatScene& flat, const std::vector<uint32_t>& deformed);
  RTCScene topLevel() const { return top_; }
  // Whether the meshes that carry filter functions are still those that need them after a material edit.
  bool filtersMatch(const FlatScene& flat) const;

 private:
  void release();

  RTCDevice device_ = nullptr;
  RTCScene top_ = nullptr;
  std::vector<RTCScene> meshScenes_;
  std::vector<bool> filtered_;  // per mesh: carries the filter functions
};

}  // namespace candela
