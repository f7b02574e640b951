#pragma once
// The two-level acceleration structure: compacted GASes of built-in triangles, one per mesh or one per batch of
// meshes, and one IAS over them. IAS instance i < firstBatchId() carries instanceId i, the index of its
// InstanceRecord in the SceneView; batch b is IAS instance firstBatchId() + b (launch_params.h).
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

// How every mesh's GAS is built; the curves' built-in intersection program is made for the same flags
// (program_modules.h).
constexpr unsigned int kMeshBuildFlags = OPTIX_BUILD_FLAG_PREFER_FAST_TRACE | OPTIX_BUILD_FLAG_ALLOW_COMPACTION;

class AccelerationStructures {
 public:
  // Brings the structures up to date with `flat`, whose arrays `device` holds on the GPU. `previous` is the
  // scene of the last update (it may be `flat` itself, after a material edit) and is only read. A mesh shares
  // the GAS of any mesh, of the previous update or built before it in this one, whose triangles it equals: the
  // same positions, indices and SBT indices. Other meshes are built; the IAS is built again when any instance
  // or the GAS it refers to changed. Where many meshes are to be built, those with one instance and one SBT
  // index for all their triangles (and, where back faces are culled, no mirroring transform) are built up to
  // kMaxBatchInputs to a GAS instead (launch_params.h), in world space and in the Morton order of their centres:
  // each optixAccelBuild call costs host time, seconds for the ten thousand meshes of a large scene
  // (docs/performance-log.md, 'Large scenes on the GPU'). A batched mesh is built again with every update that builds.
  void update(OptixDeviceContext context, cudaStream_t stream, const FlatScene* previous, const FlatScene& flat,
              const SceneView& device);

  // After FlatScene::replaceInstanceTransforms on the scene of the last update: builds the IAS again over the
  // same GASes with the new transforms. Where meshes are batched (built in world space), the batches are built
  // again too, as update() does; every other GAS is kept either way.
  void updateInstanceTransforms(OptixDeviceContext context, cudaStream_t stream, const FlatScene& flat,
                                const SceneView& device);

  OptixTraversableHandle topLevel() const { return topLevel_; }
  // For the launch parameters: the instance ids of the batches' build inputs, and the first IAS instance id
  // that is a batch.
  const uint32_t* batchInstances() const { return batchInstances_.as<const uint32_t>(); }
  uint32_t firstBatchId() const { return firstBatchId_; }
  size_t deviceBytes() const;
  const AccelerationStatistics& statistics() const { return statistics_; }

 private:
  // One mesh's GAS and what it was built from. Meshes with equal triangles share one, so that a GAS a scene
  // keeps has the same handle whichever of the equal meshes it is found through.
  struct MeshStructure {
    uint32_t meshIndex = 0;           // in the scene of the update that made or last kept it
    uint64_t key = 0;                 // meshKey: tells most different meshes apart cheaply
    std::vector<uint8_t> sbtIndices;  // per triangle (materialSbtIndex); empty where all are 0
    // The allocation that holds the GAS, with those of the meshes built in the same update; it lives while one
    // of them is kept. Null for meshes without triangles.
    std::shared_ptr<DeviceBuffer> structure;
    OptixTraversableHandle handle = 0;
    int32_t batch = -1;  // the batch whose GAS holds the mesh, or -1 where the mesh has a GAS of its own
  };
  // Meshes built into one GAS: one mesh of any kind, or a batch of meshes of one instance each.
  struct BuildGroup {
    std::vector<uint32_t> meshes;
    std::vector<uint32_t> instances;  // a batch's: the one instance of each mesh
    bool batch = false;
  };
  struct Batch {
    OptixTraversableHandle handle = 0;
    std::vector<uint32_t> instances;  // per build input
  };

  std::vector<BuildGroup> groupForBuilding(const FlatScene& flat, const std::vector<MeshStructure>& meshes,
                                           const std::vector<uint32_t>& toBuild,
                                           const std::vector<std::pair<uint32_t, uint32_t>>& sharing) const;
  void buildMeshes(OptixDeviceContext context, cudaStream_t stream, const FlatScene& flat, const SceneView& device,
                   std::vector<MeshStructure>& meshes, const std::vector<BuildGroup>& groups,
                   std::vector<Batch>& batches);
  void buildInstances(OptixDeviceContext context, cudaStream_t stream, const std::vector<OptixInstance>& instances);

  std::vector<MeshStructure> meshes_;  // one per mesh of the last update
  DeviceBuffer batchInstances_;
  uint32_t firstBatchId_ = 0xFFFFFFFFu;
  std::vector<OptixInstance> instanceList_;
  DeviceBuffer instances_;
  DeviceBuffer topLevelStructure_;
  OptixTraversableHandle topLevel_ = 0;
  AccelerationStatistics statistics_;
};

}  // namespace candela::optix
