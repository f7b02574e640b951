#include "backends/cpu/embree_scene.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "backends/cpu/embree_curve_hits.h"
#include "backends/cpu/embree_errors.h"
#include "backends/cpu/embree_pass_through.h"
#include "kernel/pass_through.h"

namespace candela {

namespace {

void check(RTCDevice device, const char* what, const FlatScene& flat) {
  RTCError error = rtcGetDeviceError(device);
  if (error != RTC_ERROR_NONE)
    throw std::runtime_error(
        embreeFailure(error, what, {flat.meshes.size(), flat.indices.size() / 3, flat.instances.size()}));
}

std::vector<bool> meshesThatCanPassRays(const FlatScene& flat) {
  std::vector<bool> result(flat.meshes.size(), false);
  if (!flat.hasCutouts) return result;
  for (size_t m = 0; m < flat.meshes.size(); ++m) {
    const MeshRecord& mesh = flat.meshes[m];
    for (uint32_t t = mesh.firstTriangle; t < mesh.firstTriangle + mesh.triangleCount && !result[m]; ++t)
      result[m] = canPassThrough(flat.materials[flat.triangleMaterials[t]]);
  }
  return result;
}

// A mesh's curves as one Embree curve geometry of their type; Embree's primitive ids are the mesh's segments.
// Copied into Embree's own buffers, which carry the padding its SIMD loads need past the last element.
RTCGeometry newCurveGeometry(RTCDevice device, const FlatScene& flat, const MeshRecord& mesh) {
  const CurveSegment* segments = flat.curveSegments.data() + mesh.firstCurveSegment;
  size_t vertexCount = 0;
  for (uint32_t s = 0; s < mesh.curveSegmentCount; ++s)
    vertexCount = std::max(vertexCount, size_t(segments[s].firstVertex) + kCurveControlPoints);
  const CurveType type = segments[0].type;
  RTCGeometry geometry =
      rtcNewGeometry(device, type == CurveType::Flat       ? RTC_GEOMETRY_TYPE_FLAT_BEZIER_CURVE
                             : type == CurveType::Cylinder ? RTC_GEOMETRY_TYPE_ROUND_BEZIER_CURVE
                                                           : RTC_GEOMETRY_TYPE_NORMAL_ORIENTED_BEZIER_CURVE);
  auto* indices = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT,
                                                                 sizeof(uint32_t), mesh.curveSegmentCount));
  auto* vertices = static_cast<Vec4*>(
      rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, sizeof(Vec4), vertexCount));
  Vec3* normals = nullptr;
  if (type == CurveType::Ribbon)
    normals = static_cast<Vec3*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_NORMAL, 0, RTC_FORMAT_FLOAT3, sizeof(Vec3), vertexCount));
  if (!indices || !vertices || (type == CurveType::Ribbon && !normals)) return geometry;  // the caller checks
  for (uint32_t s = 0; s < mesh.curveSegmentCount; ++s) indices[s] = segments[s].firstVertex;
  std::memcpy(vertices, flat.curveVertices.data() + mesh.firstCurveVertex, vertexCount * sizeof(Vec4));
  if (normals) std::memcpy(normals, flat.curveNormals.data() + mesh.firstCurveNormal, vertexCount * sizeof(Vec3));
  if (type == CurveType::Cylinder) {
    rtcSetGeometryIntersectFilterFunction(geometry, rejectCurveInsideHits);
    rtcSetGeometryOccludedFilterFunction(geometry, rejectCurveInsideHits);
  } else if (type == CurveType::Flat) {
    rtcSetGeometryIntersectFilterFunction(geometry, rejectFlatCurveSelfHits);
    rtcSetGeometryOccludedFilterFunction(geometry, rejectFlatCurveSelfHits);
  }
  return geometry;
}

}  // namespace

EmbreeScene::EmbreeScene() {
  device_ = rtcNewDevice(nullptr);
  if (!device_)
    throw std::runtime_error("Embree could not create a device (error " + std::to_string(rtcGetDeviceError(nullptr)) +
                             ")");
}

EmbreeScene::~EmbreeScene() {
  release();
  rtcReleaseDevice(device_);
}

void EmbreeScene::release() {
  for (RTCScene s : meshScenes_) rtcReleaseScene(s);
  meshScenes_.clear();
  if (top_) rtcReleaseScene(top_);
  top_ = nullptr;
}

void EmbreeScene::build(const FlatScene& flat) {
  release();
  filtered_ = meshesThatCanPassRays(flat);
  for (size_t m = 0; m < flat.meshes.size(); ++m) {
    const MeshRecord& mesh = flat.meshes[m];
    RTCScene meshScene = rtcNewScene(device_);
    if (mesh.curveSegmentCount > 0) {
      RTCGeometry geometry = newCurveGeometry(device_, flat, mesh);
      check(device_, "setting up a mesh's curves", flat);
      rtcCommitGeometry(geometry);
      rtcAttachGeometry(meshScene, geometry);
      rtcReleaseGeometry(geometry);
      rtcCommitScene(meshScene);
      check(device_, "building a curve BVH", flat);
      meshScenes_.push_back(meshScene);
      continue;
    }
    RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    // Embree's own buffers carry the padding its SIMD loads need past the last vertex.
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                 3 * sizeof(float), mesh.vertexCount));
    auto* indices = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                   3 * sizeof(uint32_t), mesh.triangleCount));
    check(device_, "allocating mesh buffers", flat);
    if (mesh.vertexCount > 0)
      std::memcpy(vertices, flat.positions.data() + mesh.firstVertex, mesh.vertexCount * sizeof(Vec3));
    if (mesh.triangleCount > 0)
      std::memcpy(indices, flat.indices.data() + 3 * size_t(mesh.firstTriangle),
                  3 * size_t(mesh.triangleCount) * sizeof(uint32_t));
    if (filtered_[m]) {
      rtcSetGeometryIntersectFilterFunction(geometry, rejectPassThroughHits);
      rtcSetGeometryOccludedFilterFunction(geometry, rejectPassThroughHits);
    }
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(meshScene, geometry);
    rtcReleaseGeometry(geometry);
    rtcSetSceneBuildQuality(meshScene, RTC_BUILD_QUALITY_HIGH);
    rtcCommitScene(meshScene);
    check(device_, "building a mesh BVH", flat);
    meshScenes_.push_back(meshScene);
  }

  top_ = rtcNewScene(device_);
  for (uint32_t i = 0; i < flat.instances.size(); ++i) {
    const InstanceRecord& inst = flat.instances[i];
    RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_INSTANCE);
    rtcSetGeometryInstancedScene(geometry, meshScenes_[inst.meshId]);
    rtcSetGeometryTransform(geometry, 0, RTC_FORMAT_FLOAT3X4_ROW_MAJOR, inst.objectToWorld.m);
    rtcCommitGeometry(geometry);
    rtcAttachGeometryByID(top_, geometry, i);
    rtcReleaseGeometry(geometry);
  }
  rtcCommitScene(top_);
  check(device_, "building the instance BVH", flat);
}

void EmbreeScene::updateInstanceTransforms(const FlatScene& flat) {
  for (uint32_t i = 0; i < flat.instances.size(); ++i) {
    RTCGeometry geometry = rtcGetGeometry(top_, i);
    rtcSetGeometryTransform(geometry, 0, RTC_FORMAT_FLOAT3X4_ROW_MAJOR, flat.instances[i].objectToWorld.m);
    rtcCommitGeometry(geometry);
  }
  rtcCommitScene(top_);
  check(device_, "building the instance BVH", flat);
}

void EmbreeScene::updateMeshVertices(const FlatScene& flat, const std::vector<uint32_t>& deformed) {
  for (uint32_t m : deformed) {
    const MeshRecord& mesh = flat.meshes[m];
    RTCGeometry geometry = rtcGetGeometry(meshScenes_[m], 0);
    auto* vertices = static_cast<float*>(rtcGetGeometryBufferData(geometry, RTC_BUFFER_TYPE_VERTEX, 0));
    if (mesh.vertexCount > 0)
      std::memcpy(vertices, flat.positions.data() + mesh.firstVertex, mesh.vertexCount * sizeof(Vec3));
    rtcUpdateGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0);
    rtcCommitGeometry(geometry);
    rtcCommitScene(meshScenes_[m]);
    check(device_, "building a deformed mesh's BVH", flat);
  }
}

bool EmbreeScene::filtersMatch(const FlatScene& flat) const { return filtered_ == meshesThatCanPassRays(flat); }

}  // namespace candela
