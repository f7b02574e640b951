#include "backends/optix/wavefront_schedule.h"

#include <optix.h>
#include <optix_stubs.h>

#include "backends/optix/optix_error.h"

namespace candela::optix {

WavefrontSchedule::WavefrontSchedule() {
  checkCuda(cudaMallocHost(&hostCounts_, 3 * sizeof(uint32_t)), "allocating the wavefront's queue lengths");
}

WavefrontSchedule::~WavefrontSchedule() { cudaFreeHost(hostCounts_); }

void WavefrontSchedule::reserve(size_t slots) {
  if (slots <= slots_) return;
  release();
  try {
    allocate(slots);
  } catch (...) {
    release();  // what did fit goes back too
    throw;
  }
  slots_ = slots;
}

void WavefrontSchedule::release() {
  slots_ = 0;
  paths_ = DeviceBuffer();
  droppedPaths_ = DeviceBuffer();
  for (int q = 0; q < 2; ++q) {
    rays_[q] = DeviceBuffer();
    rayBits_[q] = DeviceBuffer();
  }
  hits_ = DeviceBuffer();
  hitPrimitives_ = DeviceBuffer();
  shadows_ = DeviceBuffer();
}

void WavefrontSchedule::allocate(size_t slots) {
  const char* purpose = "the wavefront's paths and queues";
  paths_ = DeviceBuffer(slots * kPathPlanes * sizeof(Words4), purpose);
  droppedPaths_ = DeviceBuffer(slots * sizeof(uint32_t), purpose);
  for (int q = 0; q < 2; ++q) {
    rays_[q] = DeviceBuffer(slots * kRayPlanes * sizeof(Words4), purpose);
    rayBits_[q] = DeviceBuffer(slots * sizeof(uint32_t), purpose);
  }
  hits_ = DeviceBuffer(slots * sizeof(Words4), purpose);
  hitPrimitives_ = DeviceBuffer(slots * sizeof(uint32_t), purpose);
  shadows_ = DeviceBuffer(slots * kShadowPlanes * sizeof(Words4), purpose);
  counts_ = DeviceBuffer(3 * sizeof(uint32_t), purpose);
  for (DeviceBuffer& p : parameters_) p = DeviceBuffer(sizeof(LaunchParameters), "the launch parameters");
}

void WavefrontSchedule::enqueueSample(const Pipeline& pipeline, cudaStream_t stream, LaunchParameters p, uint32_t width,
                                      uint32_t rows, uint32_t maxDepth) {
  const size_t slots = size_t(width) * rows;
  reserve(slots);
  WavefrontBuffers& w = p.wavefront;
  w.paths = paths_.as<Words4>();
  w.droppedPaths = droppedPaths_.as<uint32_t>();
  for (int q = 0; q < 2; ++q) {
    w.rays[q] = rays_[q].as<Words4>();
    w.rayBits[q] = rayBits_[q].as<uint32_t>();
  }
  w.hits = hits_.as<Words4>();
  w.hitPrimitives = hitPrimitives_.as<uint32_t>();
  w.shadows = shadows_.as<Words4>();
  w.counts = counts_.as<uint32_t>();
  w.slots = uint32_t(slots_);
  p.samplesPerPixel = 1;
  for (uint32_t q = 0; q < 2; ++q) {
    w.current = q;
    checkCuda(cudaMemcpyAsync(parameters_[q].as<void>(), &p, sizeof p, cudaMemcpyHostToDevice, stream),
              "uploading the launch parameters");
  }
  auto launch = [&](RaygenProgram program, uint32_t queue, uint32_t launchWidth, uint32_t launchHeight) {
    checkOptix(optixLaunch(pipeline.get(), stream, parameters_[queue].address(), sizeof p,
                           &pipeline.bindingTable(program), launchWidth, launchHeight, 1),
               "launching the device programs");
  };
  launch(RaygenProgram::PathStart, 0, width, rows);
  uint32_t queued = uint32_t(slots);
  for (uint32_t bounce = 0; bounce <= maxDepth && queued > 0; ++bounce) {
    const uint32_t current = bounce & 1u, next = 1 - current;
    checkCuda(cudaMemsetAsync(counts_.as<uint32_t>() + next, 0, sizeof(uint32_t), stream), "clearing a queue");
    checkCuda(cudaMemsetAsync(counts_.as<uint32_t>() + 2, 0, sizeof(uint32_t), stream), "clearing a queue");
    launch(RaygenProgram::PathIntersect, current, queued, 1);
    launch(RaygenProgram::PathShade, current, queued, 1);
    checkCuda(cudaMemcpyAsync(hostCounts_, counts_.as<void>(), 3 * sizeof(uint32_t), cudaMemcpyDeviceToHost, stream),
              "reading the queue lengths");
    checkCuda(cudaStreamSynchronize(stream), "running the device programs");
    if (hostCounts_[2] > 0) launch(RaygenProgram::PathShadow, current, hostCounts_[2], 1);
    queued = hostCounts_[next];
  }
  launch(RaygenProgram::PathFinish, 0, width, rows);
}

}  // namespace candela::optix
