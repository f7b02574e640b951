#pragma once
#include <string>
#include <vector>

#include "backends/cpu/embree.h"
#include "scene/flat_scene.h"

namespace candela {

// Embree's view of a scene: one triangle geometry per mesh, each in its own scene, instanced into a top-level
// scene with the instance transforms. Instance and primitive ids match SceneView's.
class EmbreeScene {
 public:
  EmbreeScene();
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  void build(const FlatScene& flat);
  RTCScene topLevel() const { return top_; }

 private:
  void release();

  RTCDevice device_ = nullptr;
  RTCScene top_ = nullptr;
  std::vector<RTCScene> meshScenes_;
};

}  // namespace candela
