#pragma once
// The path tracer as a wavefront (Laine, Karras and Aila 2013; pbrt-v4's GPU renderer): instead of one thread
// following its path from ray to ray, with every kind of shading inlined around the trace calls, each bounce is
// two launches over queues of paths: trace the radiance rays (and the previous bounce's shadow rays), then shade
// the hits (kernel/path_vertex.h) and queue the shadow rays and next rays; once few paths are left, one launch
// follows them to their ends. The queues are compacted, so every launch's warps are full, and each launch's program
// is small. Paths and queues live in device memory between launches (backends/optix/wavefront_buffers.h), about
// 220 bytes a pixel. The samples are those of the one-thread schedule:
// the same numbers drawn in the same order.
#include <cuda_runtime.h>

#include <cstdint>

#include "backends/optix/device_buffer.h"
#include "backends/optix/launch_params.h"
#include "backends/optix/pipeline.h"

namespace candela::optix {

class WavefrontSchedule {
 public:
  WavefrontSchedule();
  ~WavefrontSchedule();
  WavefrontSchedule(const WavefrontSchedule&) = delete;
  WavefrontSchedule& operator=(const WavefrontSchedule&) = delete;

  // Buffers for at least `slots` paths (a launch's pixels), kept when fewer are asked for later (MultiGpuBackend
  // resizes its bands of rows every launch). Throws std::runtime_error, naming the amount, when they do not fit in
  // device memory; then none are held.
  void reserve(size_t slots);

  // Once a bounce's launches are sized for at most `paths` paths (the previous bounce's queue length), one launch
  // follows the paths left to their ends (0: never; the default is tailPaths_'s).
  void setTailPaths(uint32_t paths) { tailPaths_ = paths; }

  // Enqueues one sample per pixel (sample p.firstSample) of `rows` rows from p.firstRow on, up to `maxDepth`
  // bounces, on `stream`, with the programs of `pipeline`; the pixels' counters are left in p.counters as the
  // one-thread schedule leaves them. Waits once per bounce for a queue's length, a bounce behind the device, which
  // bounds the next launches' sizes. Reserves the buffers first (reserve()).
  void enqueueSample(const Pipeline& pipeline, cudaStream_t stream, LaunchParameters p, uint32_t width, uint32_t rows,
                     uint32_t maxDepth);

 private:
  void allocate(size_t slots);
  void release();

  size_t slots_ = 0;  // paths the buffers hold: the stride of their planes
  // Launches sized for at most this many paths follow the paths left to their ends in one launch
  // (__raygen__pathTail): by default half the current device's threads (1024 a multiprocessor). Chosen by
  // measurement on an H200 (docs/performance-log.md, 'Fewer launches and less traffic per bounce').
  uint32_t tailPaths_ = 0;
  DeviceBuffer paths_, rays_[2], rayBits_[2], hits_, hitPrimitives_, shadows_, counts_;
  // The launch parameters of the camera bounce, and of the later bounces reading radiance queue 1 and 0.
  static constexpr uint32_t kParameterSets = 3;
  DeviceBuffer parameters_[kParameterSets];
  // The radiance queues' lengths read back (pinned), and their copies' completion: a bounce's copy is read while
  // the next bounce's is under way.
  static constexpr uint32_t kCountCopies = 2;
  uint32_t* hostCounts_ = nullptr;
  cudaEvent_t countsCopied_[kCountCopies] = {};
};

}  // namespace candela::optix
