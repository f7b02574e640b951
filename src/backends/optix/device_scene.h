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

  // Same counts and constants as the host view; every pointer refers to device memory.
  const SceneView& view() const { return view_; }
  size_t deviceBytes() const;

 private:
  template <class T>
  const T* copy(const std::vector<T>& values, const char* purpose) {
    buffers_.push_back(DeviceBuffer::fromVector(values, purpose));
    return buffers_.back().as<const T>();
  }

  std::vector<DeviceBuffer> buffers_;
  DeviceTextures textures_;
  SceneView view_;
};

}  // namespace candela::optix
