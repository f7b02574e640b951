#pragma once
// A FlatScene's arrays copied to device memory, and a SceneView pointing at them.
#include <vector>

#include "backends/optix/device_buffer.h"
#include "backends/optix/device_textures.h"
#include "kernel/scene_view.h"
#include "scene/flat_scene.h"

namespace candela::optix {

class DeviceScene {
 public:
  void upload(const FlatScene& flat);
  // After FlatScene::replaceMaterials: copies the materials over the old ones (same count) and takes the
  // cut-out flag. Call only while no launch reads them.
  void updateMaterials(const FlatScene& flat);
  // After FlatScene::replaceEnvironment: uploads the environment's arrays and parameters again.
  void updateEnvironment(const FlatScene& flat);
  // After FlatScene::replaceInstanceTransforms: uploads what depends on the instances' transforms and the
  // punctual lights again: the instance records (with their normal transforms), the light table, its
  // distribution and BVH, and the punctual lights. Call only while no launch reads them.
  void updateInstances(const FlatScene& flat);

  // Same counts and constants as the host view; every pointer refers to device memory.
  const SceneView& view() const { return view_; }
  size_t deviceBytes() const;

 private:
  template <class T>
  static const T* copy(std::vector<DeviceBuffer>& into, const std::vector<T>& values, const char* purpose) {
    into.push_back(DeviceBuffer::fromVector(values, purpose));
    return into.back().as<const T>();
  }

  std::vector<DeviceBuffer> buffers_;
  DeviceBuffer materials_;
  std::vector<DeviceBuffer> environment_;
  std::vector<DeviceBuffer> posed_;  // the arrays updateInstances replaces
  DeviceTextures textures_;
  SceneView view_;
};

}  // namespace candela::optix
