#pragma once
// The two-level acceleration structure: one compacted GAS of built-in triangles per mesh, one IAS over the
// instances. IAS instance i carries instanceId i, the index of its InstanceRecord in the SceneView.
#include <cuda_runtime.h>
#include <optix_types.h>

#include <cstdint>
#include <memory>
#include <vector>

#include "backends/optix/acceleration_statistics.h"
#include "backends/optix/device_buffer.h"
#include "kernel/scene_view.h"
#include "scene/flat_scene.h"

namespace candela::optix {

// The SBT index (launch_params.h) of triangles with this material.
uint8_t materialSbtIndex(const Material& m);

class AccelerationStructures {
 public:
  // Brings the structures up to date with `flat`, whose arrays `device` holds on the GPU. `previous` is the
  // scene of the last update (it may be `flat` itself, after a material edit) and is only read. A mesh shares
  // the GAS of any mesh, of the previous update or built before it in this one, whose triangles it equals: the
  // same positions, indices and SBT indices. Other meshes are built; the IAS is built again when any instance
  // or the GAS it refers to changed.
  void update(OptixDeviceContext context, cudaStream_t stream, const FlatScene* previous, const FlatScene& flat,
              const SceneView& device);

  OptixTraversableHandle topLevel() const { return topLevel_; }
  size_t deviceBytes() const;
  const AccelerationStatistics& statistics() const { return statistics_; }

 private:
  // One mesh's GAS and what it was built from. Meshes with equal triangles share one, so that a GAS a scene
  // keeps has the same handle whichever of the equal meshes it is found through.
  struct MeshStructure {
    uint32_t meshIndex = 0;  // in the scene of the update that made or last kept it
    uint64_t key = 0;        // meshKey: tells most different meshes apart cheaply
    std::vector<uint8_t> sbtIndices;  // per triangle (materialSbtIndex); empty where all are 0
    // The allocation that holds the GAS, with those of the meshes built in the same update; it lives while one
    // of them is kept. Null for meshes without triangles.
    std::shared_ptr<DeviceBuffer> structure;
    OptixTraversableHandle handle = 0;
  };

  void buildMeshes(OptixDeviceContext context, cudaStream_t stream, const FlatScene& flat, const SceneView& device,
                   std::vector<MeshStructure>& meshes, const std::vector<size_t>& toBuild);
  void buildInstances(OptixDeviceContext context, cudaStream_t stream, const std::vector<OptixInstance>& instances);

  std::vector<MeshStructure> meshes_;  // one per mesh of the last update
  std::vector<OptixInstance> instanceList_;
  DeviceBuffer instances_;
  DeviceBuffer topLevelStructure_;
  OptixTraversableHandle topLevel_ = 0;
  AccelerationStatistics statistics_;
};

}  // namespace candela::optix
