#include "backends/optix/acceleration.h"

#include <optix.h>
#include <optix_stubs.h>

#include <algorithm>
#include <cstring>

#include "backends/optix/optix_error.h"

namespace candela::optix {

namespace {

constexpr unsigned int kGeometryFlags = OPTIX_GEOMETRY_FLAG_DISABLE_ANYHIT;  // no alpha-tested materials yet

}  // namespace

void AccelerationStructures::build(OptixDeviceContext context, cudaStream_t stream, const FlatScene& flat,
                                   const SceneView& device) {
  buildMeshes(context, stream, flat, device);
  buildInstances(context, stream, flat);
}

void AccelerationStructures::buildMeshes(OptixDeviceContext context, cudaStream_t stream, const FlatScene& flat,
                                         const SceneView& device) {
  const size_t meshCount = flat.meshes.size();
  std::vector<CUdeviceptr> vertexBuffers(meshCount);
  std::vector<OptixBuildInput> inputs(meshCount);
  for (size_t m = 0; m < meshCount; ++m) {
    const MeshRecord& mesh = flat.meshes[m];
    vertexBuffers[m] = CUdeviceptr(device.positions + mesh.firstVertex);
    OptixBuildInput& input = inputs[m];
    input.type = OPTIX_BUILD_INPUT_TYPE_TRIANGLES;
    OptixBuildInputTriangleArray& triangles = input.triangleArray;
    triangles.vertexFormat = OPTIX_VERTEX_FORMAT_FLOAT3;
    triangles.vertexStrideInBytes = sizeof(Vec3);
    triangles.numVertices = mesh.vertexCount;
    triangles.vertexBuffers = &vertexBuffers[m];
    triangles.indexFormat = OPTIX_INDICES_FORMAT_UNSIGNED_INT3;
    triangles.indexStrideInBytes = 3 * sizeof(uint32_t);
    triangles.numIndexTriplets = mesh.triangleCount;
    triangles.indexBuffer = CUdeviceptr(device.indices + 3 * size_t(mesh.firstTriangle));
    triangles.flags = &kGeometryFlags;
    triangles.numSbtRecords = 1;
  }

  OptixAccelBuildOptions options{};
  options.buildFlags = OPTIX_BUILD_FLAG_PREFER_FAST_TRACE | OPTIX_BUILD_FLAG_ALLOW_COMPACTION;
  options.operation = OPTIX_BUILD_OPERATION_BUILD;

  // Sizes first, so that one scratch buffer serves every build on the stream.
  std::vector<OptixAccelBufferSizes> sizes(meshCount);
  size_t scratchBytes = 0;
  for (size_t m = 0; m < meshCount; ++m) {
    if (flat.meshes[m].triangleCount == 0) continue;
    checkOptix(optixAccelComputeMemoryUsage(context, &options, &inputs[m], 1, &sizes[m]),
               "sizing a mesh acceleration structure");
    scratchBytes = std::max(scratchBytes, sizes[m].tempSizeInBytes);
  }
  DeviceBuffer scratch(scratchBytes, "acceleration-structure build scratch memory");
  DeviceBuffer compactedSizes(std::max<size_t>(meshCount, 1) * sizeof(uint64_t), "compacted sizes");

  std::vector<DeviceBuffer> uncompacted(meshCount);
  meshHandles_.assign(meshCount, 0);
  for (size_t m = 0; m < meshCount; ++m) {
    if (flat.meshes[m].triangleCount == 0) continue;
    uncompacted[m] = DeviceBuffer(sizes[m].outputSizeInBytes, "a mesh acceleration structure");
    OptixAccelEmitDesc emit{};
    emit.type = OPTIX_PROPERTY_TYPE_COMPACTED_SIZE;
    emit.result = compactedSizes.address() + m * sizeof(uint64_t);
    checkOptix(optixAccelBuild(context, stream, &options, &inputs[m], 1, scratch.address(), scratch.size(),
                               uncompacted[m].address(), uncompacted[m].size(), &meshHandles_[m], &emit, 1),
               "building a mesh acceleration structure");
  }
  checkCuda(cudaStreamSynchronize(stream), "building the mesh acceleration structures");

  std::vector<uint64_t> compacted(meshCount);
  compactedSizes.download(compacted.data(), meshCount * sizeof(uint64_t));
  meshStructures_.clear();
  meshStructures_.resize(meshCount);
  for (size_t m = 0; m < meshCount; ++m) {
    if (flat.meshes[m].triangleCount == 0) continue;
    if (compacted[m] >= uncompacted[m].size()) {
      meshStructures_[m] = std::move(uncompacted[m]);
      continue;
    }
    meshStructures_[m] = DeviceBuffer(compacted[m], "a compacted mesh acceleration structure");
    checkOptix(optixAccelCompact(context, stream, meshHandles_[m], meshStructures_[m].address(),
                                 meshStructures_[m].size(), &meshHandles_[m]),
               "compacting a mesh acceleration structure");
  }
  checkCuda(cudaStreamSynchronize(stream), "compacting the mesh acceleration structures");
}

void AccelerationStructures::buildInstances(OptixDeviceContext context, cudaStream_t stream,
                                            const FlatScene& flat) {
  std::vector<OptixInstance> instances;
  for (size_t i = 0; i < flat.instances.size(); ++i) {
    const InstanceRecord& record = flat.instances[i];
    if (meshHandles_[record.meshId] == 0) continue;  // nothing to hit
    OptixInstance instance{};
    std::memcpy(instance.transform, record.objectToWorld.m, sizeof instance.transform);
    instance.instanceId = uint32_t(i);
    instance.sbtOffset = 0;
    instance.visibilityMask = 0xFF;
    instance.flags = OPTIX_INSTANCE_FLAG_NONE;
    instance.traversableHandle = meshHandles_[record.meshId];
    instances.push_back(instance);
  }
  instances_ = DeviceBuffer::fromVector(instances, "the instance list");

  OptixBuildInput input{};
  input.type = OPTIX_BUILD_INPUT_TYPE_INSTANCES;
  input.instanceArray.instances = instances_.address();
  input.instanceArray.numInstances = uint32_t(instances.size());

  OptixAccelBuildOptions options{};
  options.buildFlags = OPTIX_BUILD_FLAG_PREFER_FAST_TRACE;
  options.operation = OPTIX_BUILD_OPERATION_BUILD;
  OptixAccelBufferSizes sizes{};
  checkOptix(optixAccelComputeMemoryUsage(context, &options, &input, 1, &sizes), "sizing the instance structure");
  DeviceBuffer scratch(sizes.tempSizeInBytes, "instance-structure build scratch memory");
  topLevelStructure_ = DeviceBuffer(sizes.outputSizeInBytes, "the instance acceleration structure");
  checkOptix(optixAccelBuild(context, stream, &options, &input, 1, scratch.address(), scratch.size(),
                             topLevelStructure_.address(), topLevelStructure_.size(), &topLevel_, nullptr, 0),
             "building the instance acceleration structure");
  checkCuda(cudaStreamSynchronize(stream), "building the instance acceleration structure");
}

size_t AccelerationStructures::deviceBytes() const {
  size_t total = instances_.size() + topLevelStructure_.size();
  for (const DeviceBuffer& b : meshStructures_) total += b.size();
  return total;
}

}  // namespace candela::optix
