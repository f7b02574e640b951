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
  // After FlatScene::replaceMaterials: copies the arrays uploaded WithMaterials (kernel/scene_arrays.h: the
  // materials) over the old ones (same count) and takes the cut-out flag. Call only while no launch reads them.
  void updateMaterials(const FlatScene& flat);
  // After FlatScene::replaceEnvironment: uploads the environment's arrays and parameters again.
  void updateEnvironment(const FlatScene& flat);
  // After FlatScene::replaceInstanceTransforms: uploads what depends on the instances' transforms and the
  // punctual lights again: the arrays uploaded WithInstances (kernel/scene_arrays.h: the instance records, the
  // light table, its distribution and BVH, and the punctual lights) and the light selection's constants. Call only
  // while no launch reads them.
  void updateInstances(const FlatScene& flat);

  // Same counts and constants as the host view; every pointer refers to device memory.
  const SceneView& view() const { return view_; }
  size_t deviceBytes() const;

 private:
  // Copies the listed arrays uploaded `when` to the device, each in place of its old copy, and points the view at
  // them.
  void uploadArrays(const FlatScene& flat, SceneArrayUpload when);

  template <class T>
  static const T* copy(std::vector<DeviceBuffer>& into, const std::vector<T>& values, const char* purpose) {
    into.push_back(DeviceBuffer::fromVector(values, purpose));
    return into.back().as<const T>();
  }

  // A device copy of each array of kernel/scene_arrays.h, named after it.
#define CANDELA_DEVICE_SCENE_ARRAY(Type, member, upload, count, description) DeviceBuffer member##_;
  CANDELA_SCENE_ARRAYS(CANDELA_DEVICE_SCENE_ARRAY)
#undef CANDELA_DEVICE_SCENE_ARRAY
  DeviceBuffer textureViews_;
  std::vector<DeviceBuffer> environment_;
  DeviceTextures textures_;
  SceneView view_;
};

}  // namespace candela::optix
