#pragma once
// Where the wavefront schedule keeps its paths and queues between launches (backends/optix/wavefront_schedule.h),
// as seen by the device programs. Structure of arrays: each plane holds one 16-byte word (or one 4-byte word) per
// slot, so that a warp reading or writing one plane touches consecutive memory. Stored field by field in an array
// of structures, the state cost the shading launches far more memory traffic (docs/performance-log.md).
#include <cstdint>

namespace candela::optix {

struct alignas(16) Words4 {
  uint32_t x, y, z, w;
};

// The planes of a path's state (PathState and the sampler's next dimension): which member each word holds is
// declared in backends/optix/wavefront_path_planes.h, which checks this count against it.
constexpr uint32_t kPathPlanes = 5;
// A queued radiance ray: origin + tMax, direction + path; its pass-through bits in a plane of their own.
constexpr uint32_t kRayPlanes = 2;
// A queued shadow ray: origin + tMax, direction + path, contribution + pass-through bits.
constexpr uint32_t kShadowPlanes = 3;

// The queues' lengths, in pairs that one 64-bit atomic advances together: pair q holds the length of radiance queue
// q and of the shadow queue that the same shading launch filled.
struct alignas(8) QueueCounts {
  uint32_t radiance;
  uint32_t shadow;
};

struct WavefrontBuffers {
  // kPathPlanes planes, one slot per pixel of the launch. A path whose camera ray cannot be traced has a ray count
  // of 0 in the first plane, which no traced path has: the last launch drops its sample.
  Words4* paths = nullptr;
  Words4* rays[2] = {nullptr, nullptr};  // two radiance-ray queues, kRayPlanes planes each: read one, fill the other
  uint32_t* rayBits[2] = {nullptr, nullptr};
  Words4* hits = nullptr;  // per slot of the queue read: t, b1, b2, instance (kMissedInstance: none)
  uint32_t* hitPrimitives = nullptr;
  Words4* shadows = nullptr;      // kShadowPlanes planes
  QueueCounts* counts = nullptr;  // two pairs (QueueCounts), 8-byte aligned
  uint32_t slots = 0;             // slots per plane (at least the launch's pixels)
  uint32_t current = 0;           // the radiance queue this launch reads
  uint32_t cameraBounce = 0;      // 1: this launch's paths are at their camera ray (no queue: one thread a pixel)
};

}  // namespace candela::optix
