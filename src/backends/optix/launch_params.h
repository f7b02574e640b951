#pragma once
// What host code hands the device programs for one optixLaunch, in one struct (OptiX's launch parameters).
#include <optix_types.h>

#include <cstdint>

#include "backends/optix/wavefront_buffers.h"
#include "kernel/camera.h"
#include "kernel/film.h"
#include "kernel/render_settings.h"
#include "kernel/restir/restir_buffers.h"
#include "kernel/scene_view.h"

namespace candela::optix {

// SBT offsets of the two ray types; every geometry has one hit-group record per type.
enum RayType : uint32_t { kRadianceRay = 0, kShadowRay = 1, kRayTypeCount = 2 };

// SBT indices a mesh's triangles can have (acceleration.cpp): bit 0 set where the material uses alpha (any-hit
// runs), bit 1 where it culls back faces (traversal culls them). The hit-group records of all four are the same
// programs (pipeline.cpp); the indices differ in the geometry flags the GAS gives them.
constexpr uint32_t kGeometrySbtRecords = 4;

// Meshes of one instance and no cut-outs are built many to a GAS, one build input each, when a scene has many
// (acceleration.cpp): build input k takes SBT index k, so the hit-group records repeat for as many indices as a
// batch has inputs at most, and the batch's IAS instance id (from LaunchParameters::firstBatchId on) says where
// the instance ids of its inputs lie in LaunchParameters::batchInstances.
constexpr uint32_t kMaxBatchInputs = 16384;
constexpr uint32_t kHitRecordSets = kMaxBatchInputs > kGeometrySbtRecords ? kMaxBatchInputs : kGeometrySbtRecords;

// Curves (kernel/curve.h) have hit groups of their own, with the built-in curve intersection program: their two
// records follow the triangles' sets, and the IAS instance of a mesh of curves starts its SBT there.
constexpr uint32_t kCurveSbtOffset = kHitRecordSets * kRayTypeCount;

// The radiance payload's instance register holds this when the ray missed.
constexpr uint32_t kMissedInstance = 0xFFFFFFFFu;

// What one pixel's thread did in one launch; summed over the image on the device afterwards.
struct PixelCounters {
  uint32_t rays;
  uint32_t invalidSamples;
};

struct alignas(16) RecordedRay {
  Vec3 origin;
  float tMin;
  Vec3 direction;
  float tMax;
};

// The rays of one sample per pixel, kept for the raw-trace timing mode. Slot-major ([slot][pixel]) so that a
// warp reading one slot of consecutive pixels reads consecutive memory.
struct RayRecording {
  RecordedRay* rays = nullptr;
  uint8_t* rayTypes = nullptr;  // RayType of each recorded ray
  uint32_t* counts = nullptr;   // rays recorded per pixel
  uint32_t slotsPerPixel = 0;
};

struct LaunchParameters {
  SceneView scene;
  Camera camera;
  RenderSettings settings;
  OptixTraversableHandle traversable = 0;
  uint32_t firstSample = 0;      // sample index of this launch's first sample in every pixel
  uint32_t samplesPerPixel = 0;  // samples each pixel takes in this launch
  uint32_t firstRow = 0;         // the launch covers the image's rows from here on (a band of it, or all)
  FilmView film;                 // its AOV pointers are null unless the AOVs are enabled
  PixelCounters* counters = nullptr;
  RayRecording recording;
  const uint32_t* batchInstances = nullptr;  // kMaxBatchInputs per batch: the instance id of each build input
  uint32_t firstBatchId = 0xFFFFFFFFu;       // IAS instance ids from here on are batches
  WavefrontBuffers wavefront;                // the wavefront schedule's launches only
  RestirView restir;                         // ReSTIR's launches only
};

}  // namespace candela::optix
