#include "backends/optix/acceleration.h"

#include <optix.h>
#include <optix_stubs.h>

#include <algorithm>
#include <cstring>
#include <unordered_map>
#include <unordered_set>

#include "backends/optix/launch_params.h"
#include "backends/optix/optix_error.h"
#include "kernel/pass_through.h"

namespace candela::optix {

namespace {

// Geometry flags per SBT index (launch_params.h): any-hit only where a material uses alpha; back faces culled
// (by rays that ask for it: scenes with cut-outs) only where a material culls them.
const unsigned int kGeometryFlags[kGeometrySbtRecords] = {
    OPTIX_GEOMETRY_FLAG_DISABLE_ANYHIT | OPTIX_GEOMETRY_FLAG_DISABLE_TRIANGLE_FACE_CULLING,
    OPTIX_GEOMETRY_FLAG_DISABLE_TRIANGLE_FACE_CULLING, OPTIX_GEOMETRY_FLAG_DISABLE_ANYHIT, OPTIX_GEOMETRY_FLAG_NONE};

size_t alignedSize(size_t bytes) {
  return (bytes + OPTIX_ACCEL_BUFFER_BYTE_ALIGNMENT - 1) / OPTIX_ACCEL_BUFFER_BYTE_ALIGNMENT *
         OPTIX_ACCEL_BUFFER_BYTE_ALIGNMENT;
}

uint64_t mix(uint64_t hash, uint64_t value) {
  return hash ^ (value + 0x9e3779b97f4a7c15ull + (hash << 6) + (hash >> 2));
}

// The counts and a few evenly spaced vertices and triangles: equal for equal meshes, and different for
// almost any two meshes that differ, without reading every vertex.
uint64_t meshKey(const FlatScene& flat, const MeshRecord& mesh) {
  constexpr uint32_t kSamples = 16;
  uint64_t key = mix(mix(0, mesh.vertexCount), mesh.triangleCount);
  for (uint32_t i = 0; i < kSamples && mesh.vertexCount > 0; ++i) {
    const Vec3& p = flat.positions[mesh.firstVertex + uint64_t(i) * mesh.vertexCount / kSamples];
    uint32_t bits[3];
    std::memcpy(bits, &p, sizeof bits);
    for (uint32_t b : bits) key = mix(key, b);
  }
  for (uint32_t i = 0; i < kSamples && mesh.triangleCount > 0; ++i) {
    const uint64_t t = mesh.firstTriangle + uint64_t(i) * mesh.triangleCount / kSamples;
    for (uint32_t k = 0; k < 3; ++k) key = mix(key, flat.indices[3 * t + k]);
  }
  return key;
}

bool sameTriangles(const FlatScene& a, uint32_t meshA, const FlatScene& b, uint32_t meshB) {
  const MeshRecord &ma = a.meshes[meshA], &mb = b.meshes[meshB];
  if (ma.vertexCount != mb.vertexCount || ma.triangleCount != mb.triangleCount) return false;
  const Vec3* pa = a.positions.data() + ma.firstVertex;
  const Vec3* pb = b.positions.data() + mb.firstVertex;
  const uint32_t* ia = a.indices.data() + 3 * size_t(ma.firstTriangle);
  const uint32_t* ib = b.indices.data() + 3 * size_t(mb.firstTriangle);
  if (pa == pb && ia == ib) return true;
  return std::memcmp(pa, pb, ma.vertexCount * sizeof(Vec3)) == 0 &&
         std::memcmp(ia, ib, 3 * size_t(ma.triangleCount) * sizeof(uint32_t)) == 0;
}

// Per triangle, the SBT index; empty when all are 0.
std::vector<uint8_t> sbtIndices(const FlatScene& flat, const MeshRecord& mesh) {
  std::vector<uint8_t> indices;
  if (!flat.hasCutouts) return indices;
  for (uint32_t t = 0; t < mesh.triangleCount; ++t) {
    const uint8_t index = materialSbtIndex(flat.materials[flat.triangleMaterials[mesh.firstTriangle + t]]);
    if (index != 0 && indices.empty()) indices.assign(mesh.triangleCount, 0);
    if (index != 0) indices[t] = index;
  }
  return indices;
}

}  // namespace

uint8_t materialSbtIndex(const Material& m) { return uint8_t((usesAlpha(m) ? 1 : 0) | (cullsBackFaces(m) ? 2 : 0)); }

void AccelerationStructures::update(OptixDeviceContext context, cudaStream_t stream, const FlatScene* previous,
                                    const FlatScene& flat, const SceneView& device) {
  std::unordered_multimap<uint64_t, size_t> previousByKey;
  if (previous)
    for (size_t i = 0; i < meshes_.size(); ++i) previousByKey.emplace(meshes_[i].key, i);

  std::vector<MeshStructure> meshes(flat.meshes.size());
  std::vector<size_t> toBuild;
  std::unordered_multimap<uint64_t, uint32_t> earlierByKey;  // meshes of this update that own a GAS
  std::vector<std::pair<uint32_t, uint32_t>> sharing;        // a mesh, and the earlier one it equals
  for (uint32_t m = 0; m < flat.meshes.size(); ++m) {
    const MeshRecord& mesh = flat.meshes[m];
    MeshStructure& s = meshes[m];
    s.meshIndex = m;
    s.key = meshKey(flat, mesh);
    s.sbtIndices = sbtIndices(flat, mesh);
    if (mesh.triangleCount == 0) continue;
    auto equals = [&](const MeshStructure& other, const FlatScene& otherScene) {
      return other.sbtIndices == s.sbtIndices && sameTriangles(otherScene, other.meshIndex, flat, m);
    };
    auto [firstEarlier, lastEarlier] = earlierByKey.equal_range(s.key);
    auto earlier = std::find_if(firstEarlier, lastEarlier, [&](const auto& e) { return equals(meshes[e.second], flat); });
    if (earlier != lastEarlier) {
      sharing.emplace_back(m, earlier->second);
      continue;
    }
    auto [firstOld, lastOld] = previousByKey.equal_range(s.key);
    auto old = std::find_if(firstOld, lastOld, [&](const auto& e) { return equals(meshes_[e.second], *previous); });
    if (old != lastOld) {
      s.structure = meshes_[old->second].structure;
      s.handle = meshes_[old->second].handle;
    } else {
      toBuild.push_back(m);
    }
    earlierByKey.emplace(s.key, m);
  }
  buildMeshes(context, stream, flat, device, meshes, toBuild);
  for (auto [m, earlierMesh] : sharing) {
    meshes[m].structure = meshes[earlierMesh].structure;
    meshes[m].handle = meshes[earlierMesh].handle;
  }

  std::vector<OptixInstance> instances;
  for (size_t i = 0; i < flat.instances.size(); ++i) {
    const InstanceRecord& record = flat.instances[i];
    if (meshes[record.meshId].handle == 0) continue;  // nothing to hit
    OptixInstance instance{};
    std::memcpy(instance.transform, record.objectToWorld.m, sizeof instance.transform);
    instance.instanceId = uint32_t(i);
    instance.sbtOffset = 0;
    instance.visibilityMask = 0xFF;
    instance.flags = OPTIX_INSTANCE_FLAG_NONE;
    instance.traversableHandle = meshes[record.meshId].handle;
    instances.push_back(instance);
  }
  // A GAS built now has a new handle (the GASes it could share an address with are still alive), so an
  // unchanged list means an unchanged IAS.
  const bool instancesChanged =
      statistics_.instanceBuilds == 0 || instances.size() != instanceList_.size() ||
      std::memcmp(instances.data(), instanceList_.data(), instances.size() * sizeof(OptixInstance)) != 0;
  if (instancesChanged) buildInstances(context, stream, instances);
  meshes_ = std::move(meshes);
  instanceList_ = std::move(instances);
  statistics_.meshBuilds += toBuild.size();
  if (instancesChanged) ++statistics_.instanceBuilds;
}

void AccelerationStructures::buildMeshes(OptixDeviceContext context, cudaStream_t stream, const FlatScene& flat,
                                         const SceneView& device, std::vector<MeshStructure>& meshes,
                                         const std::vector<size_t>& toBuild) {
  if (toBuild.empty()) return;
  const size_t count = toBuild.size();
  std::vector<CUdeviceptr> vertexBuffers(count);
  std::vector<OptixBuildInput> inputs(count);
  std::vector<DeviceBuffer> sbtIndexBuffers(count);
  for (size_t b = 0; b < count; ++b) {
    const MeshRecord& mesh = flat.meshes[toBuild[b]];
    const std::vector<uint8_t>& sbt = meshes[toBuild[b]].sbtIndices;
    vertexBuffers[b] = CUdeviceptr(device.positions + mesh.firstVertex);
    OptixBuildInput& input = inputs[b];
    input.type = OPTIX_BUILD_INPUT_TYPE_TRIANGLES;
    OptixBuildInputTriangleArray& triangles = input.triangleArray;
    triangles.vertexFormat = OPTIX_VERTEX_FORMAT_FLOAT3;
    triangles.vertexStrideInBytes = sizeof(Vec3);
    triangles.numVertices = mesh.vertexCount;
    triangles.vertexBuffers = &vertexBuffers[b];
    triangles.indexFormat = OPTIX_INDICES_FORMAT_UNSIGNED_INT3;
    triangles.indexStrideInBytes = 3 * sizeof(uint32_t);
    triangles.numIndexTriplets = mesh.triangleCount;
    triangles.indexBuffer = CUdeviceptr(device.indices + 3 * size_t(mesh.firstTriangle));
    triangles.numSbtRecords = 1;
    if (sbt.empty()) {
      triangles.flags = &kGeometryFlags[0];
    } else if (std::all_of(sbt.begin(), sbt.end(), [&](uint8_t i) { return i == sbt[0]; })) {
      triangles.flags = &kGeometryFlags[sbt[0]];
    } else {
      sbtIndexBuffers[b] = DeviceBuffer::fromVector(sbt, "a mesh's SBT indices");
      triangles.flags = kGeometryFlags;
      triangles.numSbtRecords = kGeometrySbtRecords;
      triangles.sbtIndexOffsetBuffer = sbtIndexBuffers[b].address();
      triangles.sbtIndexOffsetSizeInBytes = sizeof(uint8_t);
      triangles.sbtIndexOffsetStrideInBytes = sizeof(uint8_t);
    }
  }

  OptixAccelBuildOptions options{};
  options.buildFlags = OPTIX_BUILD_FLAG_PREFER_FAST_TRACE | OPTIX_BUILD_FLAG_ALLOW_COMPACTION;
  options.operation = OPTIX_BUILD_OPERATION_BUILD;

  // Sizes first, so that one scratch buffer serves every build on the stream, and one allocation holds every
  // GAS before compaction and one every GAS after: scenes have tens of thousands of meshes, and a cudaMalloc and
  // cudaFree per GAS took seconds for them.
  std::vector<OptixAccelBufferSizes> sizes(count);
  std::vector<size_t> offsets(count);
  size_t scratchBytes = 0, uncompactedBytes = 0;
  for (size_t b = 0; b < count; ++b) {
    checkOptix(optixAccelComputeMemoryUsage(context, &options, &inputs[b], 1, &sizes[b]),
               "sizing a mesh acceleration structure");
    scratchBytes = std::max(scratchBytes, sizes[b].tempSizeInBytes);
    offsets[b] = uncompactedBytes;
    uncompactedBytes += alignedSize(sizes[b].outputSizeInBytes);
  }
  DeviceBuffer scratch(scratchBytes, "acceleration-structure build scratch memory");
  DeviceBuffer uncompacted(uncompactedBytes, "the mesh acceleration structures before compaction");
  DeviceBuffer compactedSizes(count * sizeof(uint64_t), "compacted sizes");

  std::vector<OptixTraversableHandle> handles(count, 0);
  for (size_t b = 0; b < count; ++b) {
    OptixAccelEmitDesc emit{};
    emit.type = OPTIX_PROPERTY_TYPE_COMPACTED_SIZE;
    emit.result = compactedSizes.address() + b * sizeof(uint64_t);
    checkOptix(optixAccelBuild(context, stream, &options, &inputs[b], 1, scratch.address(), scratch.size(),
                               uncompacted.address() + offsets[b], sizes[b].outputSizeInBytes, &handles[b], &emit, 1),
               "building a mesh acceleration structure");
  }
  checkCuda(cudaStreamSynchronize(stream), "building the mesh acceleration structures");

  std::vector<uint64_t> compactedSize(count);
  compactedSizes.download(compactedSize.data(), count * sizeof(uint64_t));
  size_t compactedBytes = 0;
  for (size_t b = 0; b < count; ++b) {
    offsets[b] = compactedBytes;
    compactedBytes += alignedSize(compactedSize[b]);
  }
  auto compacted = std::make_shared<DeviceBuffer>(compactedBytes, "the mesh acceleration structures");
  for (size_t b = 0; b < count; ++b) {
    MeshStructure& s = meshes[toBuild[b]];
    s.structure = compacted;
    checkOptix(optixAccelCompact(context, stream, handles[b], compacted->address() + offsets[b], compactedSize[b],
                                 &s.handle),
               "compacting a mesh acceleration structure");
  }
  checkCuda(cudaStreamSynchronize(stream), "compacting the mesh acceleration structures");
}

void AccelerationStructures::buildInstances(OptixDeviceContext context, cudaStream_t stream,
                                            const std::vector<OptixInstance>& instances) {
  DeviceBuffer instanceBuffer = DeviceBuffer::fromVector(instances, "the instance list");
  OptixBuildInput input{};
  input.type = OPTIX_BUILD_INPUT_TYPE_INSTANCES;
  input.instanceArray.instances = instanceBuffer.address();
  input.instanceArray.numInstances = uint32_t(instances.size());

  OptixAccelBuildOptions options{};
  options.buildFlags = OPTIX_BUILD_FLAG_PREFER_FAST_TRACE;
  options.operation = OPTIX_BUILD_OPERATION_BUILD;
  OptixAccelBufferSizes sizes{};
  checkOptix(optixAccelComputeMemoryUsage(context, &options, &input, 1, &sizes), "sizing the instance structure");
  DeviceBuffer scratch(sizes.tempSizeInBytes, "instance-structure build scratch memory");
  DeviceBuffer structure(sizes.outputSizeInBytes, "the instance acceleration structure");
  OptixTraversableHandle handle = 0;
  checkOptix(optixAccelBuild(context, stream, &options, &input, 1, scratch.address(), scratch.size(),
                             structure.address(), structure.size(), &handle, nullptr, 0),
             "building the instance acceleration structure");
  checkCuda(cudaStreamSynchronize(stream), "building the instance acceleration structure");
  instances_ = std::move(instanceBuffer);
  topLevelStructure_ = std::move(structure);
  topLevel_ = handle;
}

size_t AccelerationStructures::deviceBytes() const {
  size_t total = instances_.size() + topLevelStructure_.size();
  std::unordered_set<const DeviceBuffer*> counted;
  for (const MeshStructure& s : meshes_)
    if (s.structure && counted.insert(s.structure.get()).second) total += s.structure->size();
  return total;
}

}  // namespace candela::optix
