#include "backends/optix/acceleration.h"

#include <optix.h>
#include <optix_stubs.h>

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include "backends/optix/launch_params.h"
#include "backends/optix/optix_error.h"
#include "core/bounds.h"
#include "kernel/pass_through.h"

namespace candela::optix {

namespace {

// Geometry flags per SBT index (launch_params.h): any-hit only where a material uses alpha; back faces culled
// (by rays that ask for it: scenes with cut-outs) only where a material culls them.
const unsigned int kGeometryFlags[kGeometrySbtRecords] = {OPTIX_GEOMETRY_FLAG_DISABLE_ANYHIT |
                                                              OPTIX_GEOMETRY_FLAG_DISABLE_TRIANGLE_FACE_CULLING,
                                                          OPTIX_GEOMETRY_FLAG_DISABLE_TRIANGLE_FACE_CULLING,
                                                          OPTIX_GEOMETRY_FLAG_DISABLE_ANYHIT, OPTIX_GEOMETRY_FLAG_NONE};

// Below this many meshes to build, each gets a GAS of its own.
constexpr size_t kMinMeshesToBatch = 256;

// The 63-bit Morton code of `p` on a 2^21 grid over the box [lo, hi].
uint64_t mortonCode(Vec3 p, Vec3 lo, Vec3 hi) {
  auto spread = [](uint64_t x) {  // the 21 bits of x, two zero bits after each
    x &= 0x1fffff;
    x = (x | x << 32) & 0x1f00000000ffffull;
    x = (x | x << 16) & 0x1f0000ff0000ffull;
    x = (x | x << 8) & 0x100f00f00f00f00full;
    x = (x | x << 4) & 0x10c30c30c30c30c3ull;
    x = (x | x << 2) & 0x1249249249249249ull;
    return x;
  };
  auto cell = [](float v, float a, float b) {
    const float t = b > a ? (v - a) / (b - a) : 0.0f;
    return uint64_t(std::clamp(t, 0.0f, 1.0f) * float((1u << 21) - 1));
  };
  return spread(cell(p.x, lo.x, hi.x)) << 2 | spread(cell(p.y, lo.y, hi.y)) << 1 | spread(cell(p.z, lo.z, hi.z));
}

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

// The SBT index all of a mesh's triangles have (sbtIndices), or -1 where they differ.
int uniformSbtIndex(const std::vector<uint8_t>& sbt) {
  if (sbt.empty()) return 0;
  return std::all_of(sbt.begin(), sbt.end(), [&](uint8_t i) { return i == sbt[0]; }) ? sbt[0] : -1;
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

// A mesh's curves as one build input of round cubic Bezier curves, read in place from the device copy of the flat
// arrays (kernel/curve.h): the control points' xyz and, 12 bytes on, their radii (OptiX's widths), both 16 bytes
// apart; each segment's first control point, sizeof(CurveSegment) apart. Curves take one SBT record (the
// curves' hit groups, kCurveSbtOffset), whose any-hit program passes the tubes' inner walls.
void setCurveInput(const FlatScene& flat, const MeshRecord& mesh, const SceneView& device, CUdeviceptr& vertices,
                   CUdeviceptr& widths, OptixBuildInput& input) {
  uint32_t vertexCount = 0;
  for (uint32_t s = 0; s < mesh.curveSegmentCount; ++s)
    vertexCount =
        std::max(vertexCount, flat.curveSegments[mesh.firstCurveSegment + s].firstVertex + kCurveControlPoints);
  vertices = CUdeviceptr(device.curveVertices + mesh.firstCurveVertex);
  widths = vertices + offsetof(Vec4, w);
  input.type = OPTIX_BUILD_INPUT_TYPE_CURVES;
  OptixBuildInputCurveArray& curves = input.curveArray;
  curves.curveType = OPTIX_PRIMITIVE_TYPE_ROUND_CUBIC_BEZIER;
  curves.numPrimitives = mesh.curveSegmentCount;
  curves.vertexBuffers = &vertices;
  curves.numVertices = vertexCount;
  curves.vertexStrideInBytes = sizeof(Vec4);
  curves.widthBuffers = &widths;
  curves.widthStrideInBytes = sizeof(Vec4);
  curves.indexBuffer = CUdeviceptr(device.curveSegments + mesh.firstCurveSegment) + offsetof(CurveSegment, firstVertex);
  curves.indexStrideInBytes = sizeof(CurveSegment);
  curves.flag = OPTIX_GEOMETRY_FLAG_NONE;  // their any-hit program passes the tubes' inner walls
  curves.endcapFlags = OPTIX_CURVE_ENDCAP_DEFAULT;
}

}  // namespace

uint8_t materialSbtIndex(const Material& m) { return uint8_t((usesAlpha(m) ? 1 : 0) | (cullsBackFaces(m) ? 2 : 0)); }

void AccelerationStructures::update(OptixDeviceContext context, cudaStream_t stream, const FlatScene* previous,
                                    const FlatScene& flat, const SceneView& device) {
  std::unordered_multimap<uint64_t, size_t> previousByKey;
  if (previous)
    for (size_t i = 0; i < meshes_.size(); ++i)
      if (meshes_[i].batch < 0) previousByKey.emplace(meshes_[i].key, i);

  std::vector<MeshStructure> meshes(flat.meshes.size());
  std::vector<uint32_t> toBuild;
  std::unordered_multimap<uint64_t, uint32_t> earlierByKey;  // meshes of this update that own a GAS
  std::vector<std::pair<uint32_t, uint32_t>> sharing;        // a mesh, and the earlier one it equals
  for (uint32_t m = 0; m < flat.meshes.size(); ++m) {
    const MeshRecord& mesh = flat.meshes[m];
    MeshStructure& s = meshes[m];
    s.meshIndex = m;
    s.key = meshKey(flat, mesh);
    s.sbtIndices = sbtIndices(flat, mesh);
    // Curves are built anew with every update that builds: neither shared nor kept (their key sees no curve).
    if (mesh.curveSegmentCount > 0) {
      toBuild.push_back(m);
      continue;
    }
    if (mesh.triangleCount == 0) continue;
    auto equals = [&](const MeshStructure& other, const FlatScene& otherScene) {
      return other.sbtIndices == s.sbtIndices && sameTriangles(otherScene, other.meshIndex, flat, m);
    };
    auto [firstEarlier, lastEarlier] = earlierByKey.equal_range(s.key);
    auto earlier =
        std::find_if(firstEarlier, lastEarlier, [&](const auto& e) { return equals(meshes[e.second], flat); });
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
  std::vector<Batch> batches;
  buildMeshes(context, stream, flat, device, meshes, groupForBuilding(flat, meshes, toBuild, sharing), batches);
  for (auto [m, earlierMesh] : sharing) {
    meshes[m].structure = meshes[earlierMesh].structure;
    meshes[m].handle = meshes[earlierMesh].handle;
  }

  std::vector<OptixInstance> instances;
  auto addInstance = [&](const float(&transform)[12], uint32_t id, OptixTraversableHandle handle, uint32_t sbtOffset) {
    OptixInstance instance{};
    std::memcpy(instance.transform, transform, sizeof instance.transform);
    instance.instanceId = id;
    instance.sbtOffset = sbtOffset;
    instance.visibilityMask = 0xFF;
    instance.flags = OPTIX_INSTANCE_FLAG_NONE;
    instance.traversableHandle = handle;
    instances.push_back(instance);
  };
  for (size_t i = 0; i < flat.instances.size(); ++i) {
    const InstanceRecord& record = flat.instances[i];
    // Batched meshes are reached through their batch; meshes without triangles or curves have nothing to hit.
    if (meshes[record.meshId].batch >= 0 || meshes[record.meshId].handle == 0) continue;
    addInstance(record.objectToWorld.m, uint32_t(i), meshes[record.meshId].handle,
                flat.meshes[record.meshId].curveSegmentCount > 0 ? kCurveSbtOffset : 0);
  }
  firstBatchId_ = uint32_t(flat.instances.size());
  const float identity[12] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
  std::vector<uint32_t> batchInstances(batches.size() * kMaxBatchInputs, 0);
  for (size_t b = 0; b < batches.size(); ++b) {
    addInstance(identity, firstBatchId_ + uint32_t(b), batches[b].handle, 0);
    std::copy(batches[b].instances.begin(), batches[b].instances.end(), batchInstances.begin() + b * kMaxBatchInputs);
  }
  batchInstances_ = DeviceBuffer::fromVector(batchInstances, "the instances of batched meshes");
  // A GAS built now has a new handle (the GASes it could share an address with are still alive), so an
  // unchanged list means an unchanged IAS.
  const bool instancesChanged =
      statistics_.instanceBuilds == 0 || instances.size() != instanceList_.size() ||
      std::memcmp(instances.data(), instanceList_.data(), instances.size() * sizeof(OptixInstance)) != 0;
  if (instancesChanged) buildInstances(context, stream, instances);
  meshes_ = std::move(meshes);
  instanceList_ = std::move(instances);
  statistics_.meshBuilds += toBuild.size();
  for (const Batch& batch : batches) statistics_.batchedMeshes += batch.instances.size();
  if (instancesChanged) ++statistics_.instanceBuilds;
}

void AccelerationStructures::updateInstanceTransforms(OptixDeviceContext context, cudaStream_t stream,
                                                      const FlatScene& flat, const SceneView& device) {
  const bool batched = std::any_of(meshes_.begin(), meshes_.end(), [](const MeshStructure& m) { return m.batch >= 0; });
  if (batched || meshes_.size() != flat.meshes.size()) return update(context, stream, &flat, flat, device);
  // Without batches every IAS instance is one of the scene's, its instanceId the index of its record.
  for (OptixInstance& instance : instanceList_)
    std::memcpy(instance.transform, flat.instances[instance.instanceId].objectToWorld.m, sizeof instance.transform);
  buildInstances(context, stream, instanceList_);
  ++statistics_.instanceBuilds;
}

std::vector<AccelerationStructures::BuildGroup> AccelerationStructures::groupForBuilding(
    const FlatScene& flat, const std::vector<MeshStructure>& meshes, const std::vector<uint32_t>& toBuild,
    const std::vector<std::pair<uint32_t, uint32_t>>& sharing) const {
  std::vector<BuildGroup> groups;
  std::vector<uint32_t> instanceCount(flat.meshes.size(), 0);
  for (const InstanceRecord& record : flat.instances) ++instanceCount[record.meshId];
  std::vector<bool> sharedWith(flat.meshes.size(), false);  // a mesh whose GAS a later mesh takes
  for (auto [m, earlierMesh] : sharing) sharedWith[earlierMesh] = true;
  std::vector<uint32_t> instanceOf(flat.meshes.size(), 0);
  for (uint32_t i = 0; i < flat.instances.size(); ++i) instanceOf[flat.instances[i].meshId] = i;
  // A batch's triangles share one SBT index (geometry flags); culling, where the flags ask for it, is decided by
  // the winding in world space, which a mirroring transform turns over.
  auto batchClass = [&](uint32_t m) -> int {
    if (instanceCount[m] != 1 || sharedWith[m] || flat.meshes[m].curveSegmentCount > 0) return -1;
    const int sbtIndex = uniformSbtIndex(meshes[m].sbtIndices);
    if (sbtIndex < 0) return -1;
    if ((sbtIndex & 2) && !(flat.instances[instanceOf[m]].objectToWorld.determinant() > 0.0f)) return -1;
    return sbtIndex;
  };
  const bool batching = toBuild.size() >= kMinMeshesToBatch;
  std::vector<std::vector<uint32_t>> batchable(kGeometrySbtRecords);  // per SBT index
  for (uint32_t m : toBuild) {
    const int sbtIndex = batching ? batchClass(m) : -1;
    if (sbtIndex < 0)
      groups.push_back({{m}, {}, false});
    else
      batchable[size_t(sbtIndex)].push_back(m);
  }
  // Batches of meshes near each other, so that the batches' boxes overlap little in the IAS: the meshes in the
  // Morton order of their world-space centres.
  std::vector<Vec3> centre(flat.meshes.size());
  Bounds3 centres;
  for (const std::vector<uint32_t>& list : batchable)
    for (uint32_t m : list) {
      const MeshRecord& mesh = flat.meshes[m];
      Bounds3 meshBounds;
      for (uint32_t v = 0; v < mesh.vertexCount; ++v) meshBounds.extend(flat.positions[mesh.firstVertex + v]);
      centre[m] = flat.instances[instanceOf[m]].objectToWorld.point(meshBounds.centre());
      centres.extend(centre[m]);
    }
  for (std::vector<uint32_t>& list : batchable) {
    std::vector<std::pair<uint64_t, uint32_t>> ordered;
    for (uint32_t m : list) ordered.emplace_back(mortonCode(centre[m], centres.lo, centres.hi), m);
    std::sort(ordered.begin(), ordered.end());
    for (size_t first = 0; first < ordered.size(); first += kMaxBatchInputs) {
      BuildGroup batch{{}, {}, true};
      for (size_t i = first; i < std::min(first + kMaxBatchInputs, ordered.size()); ++i) {
        batch.meshes.push_back(ordered[i].second);
        batch.instances.push_back(instanceOf[ordered[i].second]);
      }
      groups.push_back(std::move(batch));
    }
  }
  return groups;
}

void AccelerationStructures::buildMeshes(OptixDeviceContext context, cudaStream_t stream, const FlatScene& flat,
                                         const SceneView& device, std::vector<MeshStructure>& meshes,
                                         const std::vector<BuildGroup>& groups, std::vector<Batch>& batches) {
  if (groups.empty()) return;
  size_t inputCount = 0, batchedCount = 0;
  for (const BuildGroup& g : groups) {
    inputCount += g.meshes.size();
    if (g.batch) batchedCount += g.meshes.size();
  }
  // A batched mesh is built in world space: its one instance's transform is applied during the build.
  std::vector<float> transforms;
  transforms.reserve(batchedCount * 12);
  for (const BuildGroup& g : groups)
    for (uint32_t i : g.instances)
      transforms.insert(transforms.end(), std::begin(flat.instances[i].objectToWorld.m),
                        std::end(flat.instances[i].objectToWorld.m));
  const DeviceBuffer transformBuffer = DeviceBuffer::fromVector(transforms, "the transforms of batched meshes");

  std::vector<CUdeviceptr> vertexBuffers(inputCount), widthBuffers(inputCount);
  std::vector<OptixBuildInput> inputs(inputCount);
  std::vector<DeviceBuffer> sbtIndexBuffers(inputCount);
  size_t next = 0, nextTransform = 0;
  for (const BuildGroup& g : groups)
    for (uint32_t m : g.meshes) {
      const size_t b = next++;
      const MeshRecord& mesh = flat.meshes[m];
      if (mesh.curveSegmentCount > 0) {
        setCurveInput(flat, mesh, device, vertexBuffers[b], widthBuffers[b], inputs[b]);
        continue;
      }
      const std::vector<uint8_t>& sbt = meshes[m].sbtIndices;
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
      if (g.batch) {
        triangles.preTransform = transformBuffer.address() + nextTransform++ * 12 * sizeof(float);
        triangles.transformFormat = OPTIX_TRANSFORM_FORMAT_MATRIX_FLOAT12;
      }
      const int sbtIndex = uniformSbtIndex(sbt);
      if (sbtIndex >= 0) {
        triangles.flags = &kGeometryFlags[sbtIndex];
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
  options.buildFlags = kMeshBuildFlags;
  options.operation = OPTIX_BUILD_OPERATION_BUILD;

  // Sizes first, so that one scratch buffer serves every build on the stream, and one allocation holds every
  // GAS before compaction and one every GAS after.
  const size_t count = groups.size();
  std::vector<size_t> firstInput(count);
  std::vector<OptixAccelBufferSizes> sizes(count);
  std::vector<size_t> offsets(count);
  size_t scratchBytes = 0, uncompactedBytes = 0;
  for (size_t g = 0, input = 0; g < count; input += groups[g].meshes.size(), ++g) {
    firstInput[g] = input;
    checkOptix(optixAccelComputeMemoryUsage(context, &options, &inputs[input], uint32_t(groups[g].meshes.size()),
                                            &sizes[g]),
               "sizing a mesh acceleration structure");
    scratchBytes = std::max(scratchBytes, sizes[g].tempSizeInBytes);
    offsets[g] = uncompactedBytes;
    uncompactedBytes += alignedSize(sizes[g].outputSizeInBytes);
  }
  DeviceBuffer scratch(scratchBytes, "acceleration-structure build scratch memory");
  DeviceBuffer uncompacted(uncompactedBytes, "the mesh acceleration structures before compaction");
  DeviceBuffer compactedSizes(count * sizeof(uint64_t), "compacted sizes");

  std::vector<OptixTraversableHandle> handles(count, 0);
  for (size_t g = 0; g < count; ++g) {
    OptixAccelEmitDesc emit{};
    emit.type = OPTIX_PROPERTY_TYPE_COMPACTED_SIZE;
    emit.result = compactedSizes.address() + g * sizeof(uint64_t);
    checkOptix(optixAccelBuild(context, stream, &options, &inputs[firstInput[g]], uint32_t(groups[g].meshes.size()),
                               scratch.address(), scratch.size(), uncompacted.address() + offsets[g],
                               sizes[g].outputSizeInBytes, &handles[g], &emit, 1),
               "building a mesh acceleration structure");
  }
  checkCuda(cudaStreamSynchronize(stream), "building the mesh acceleration structures");

  std::vector<uint64_t> compactedSize(count);
  compactedSizes.download(compactedSize.data(), count * sizeof(uint64_t));
  size_t compactedBytes = 0;
  for (size_t g = 0; g < count; ++g) {
    offsets[g] = compactedBytes;
    compactedBytes += alignedSize(compactedSize[g]);
  }
  auto compacted = std::make_shared<DeviceBuffer>(compactedBytes, "the mesh acceleration structures");
  for (size_t g = 0; g < count; ++g) {
    OptixTraversableHandle handle = 0;
    checkOptix(optixAccelCompact(context, stream, handles[g], compacted->address() + offsets[g], compactedSize[g],
                                 &handle),
               "compacting a mesh acceleration structure");
    const BuildGroup& group = groups[g];
    if (group.batch) {
      for (uint32_t m : group.meshes) {
        meshes[m].structure = compacted;
        meshes[m].batch = int32_t(batches.size());
      }
      batches.push_back({handle, group.instances});
    } else {
      meshes[group.meshes[0]].structure = compacted;
      meshes[group.meshes[0]].handle = handle;
    }
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
  size_t total = instances_.size() + topLevelStructure_.size() + batchInstances_.size();
  std::unordered_set<const DeviceBuffer*> counted;
  for (const MeshStructure& s : meshes_)
    if (s.structure && counted.insert(s.structure.get()).second) total += s.structure->size();
  return total;
}

}  // namespace candela::optix
