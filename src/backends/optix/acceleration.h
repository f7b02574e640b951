#pragma once
// The two-level acceleration structure: one compacted GAS of built-in triangles per mesh, one IAS over the
// instances. IAS instance i carries instanceId i, the index of its InstanceRecord in the SceneView.
#include <cuda_runtime.h>
#include <optix_types.h>

#include <vector>

#include "backends/optix/device_buffer.h"
#include "kernel/scene_view.h"
#include "scene/flat_scene.h"

namespace candela::optix {

class AccelerationStructures {
 public:
  // `device` is the uploaded copy of `flat`: the GAS builds read vertices and indices from it.
  void build(OptixDeviceContext context, cudaStream_t stream, const FlatScene& flat, const SceneView& device);

  OptixTraversableHandle topLevel() const { return topLevel_; }
  size_t deviceBytes() const;

 private:
  void buildMeshes(OptixDeviceContext context, cudaStream_t stream, const FlatScene& flat, const SceneView& device);
  void buildInstances(OptixDeviceContext context, cudaStream_t stream, const FlatScene& flat);

  std::vector<DeviceBuffer> meshStructures_;
  std::vector<OptixTraversableHandle> meshHandles_;  // 0 for meshes without triangles
  DeviceBuffer instances_;
  DeviceBuffer topLevelStructure_;
  OptixTraversableHandle topLevel_ = 0;
};

}  // namespace candela::optix
