#include "backends/optix/wavefront_schedule.h"

#include <optix.h>
#include <optix_stubs.h>

#include "backends/optix/optix_error.h"

namespace candela::optix {

WavefrontSchedule::WavefrontSchedule() {
  int device = 0, multiprocessors = 0;
  checkCuda(cudaGetDevice(&device), "finding the current CUDA device");
  checkCuda(cudaDeviceGetAttribute(&multiprocessors, cudaDevAttrMultiProcessorCount, device),
            "counting the device's multiprocessors");
  tailPaths_ = uint32_t(multiprocessors) * 1024u;
  checkCuda(cudaMallocHost(&hostCounts_, kCountCopies * sizeof(uint32_t)), "allocating the wavefront's queue lengths");
  for (cudaEvent_t& copied : countsCopied_)
    checkCuda(cudaEventCreateWithFlags(&copied, cudaEventDisableTiming), "creating an event");
}

WavefrontSchedule::~WavefrontSchedule() {
  for (cudaEvent_t copied : countsCopied_) cudaEventDestroy(copied);
  cudaFreeHost(hostCounts_);
}

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
  for (int q = 0; q < 2; ++q) {
    rays_[q] = DeviceBuffer(slots * kRayPlanes * sizeof(Words4), purpose);
    rayBits_[q] = DeviceBuffer(slots * sizeof(uint32_t), purpose);
  }
  hits_ = DeviceBuffer(slots * sizeof(Words4), purpose);
  hitPrimitives_ = DeviceBuffer(slots * sizeof(uint32_t), purpose);
  shadows_ = DeviceBuffer(slots * kShadowPlanes * sizeof(Words4), purpose);
  counts_ = DeviceBuffer(2 * sizeof(QueueCounts), purpose);
  for (DeviceBuffer& p : parameters_) p = DeviceBuffer(sizeof(LaunchParameters), "the launch parameters");
}

void WavefrontSchedule::enqueueSample(const Pipeline& pipeline, cudaStream_t stream, LaunchParameters p, uint32_t width,
                                      uint32_t rows, uint32_t maxDepth) {
  const size_t slots = size_t(width) * rows;
  reserve(slots);
  WavefrontBuffers& w = p.wavefront;
  w.paths = paths_.as<Words4>();
  for (int q = 0; q < 2; ++q) {
    w.rays[q] = rays_[q].as<Words4>();
    w.rayBits[q] = rayBits_[q].as<uint32_t>();
  }
  w.hits = hits_.as<Words4>();
  w.hitPrimitives = hitPrimitives_.as<uint32_t>();
  w.shadows = shadows_.as<Words4>();
  QueueCounts* counts = counts_.as<QueueCounts>();
  w.counts = counts;
  w.slots = uint32_t(slots_);
  p.samplesPerPixel = 1;
  for (uint32_t set = 0; set < kParameterSets; ++set) {
    w.current = set & 1u;
    w.cameraBounce = set == 0 ? 1u : 0u;
    checkCuda(cudaMemcpyAsync(parameters_[set].as<void>(), &p, sizeof p, cudaMemcpyHostToDevice, stream),
              "uploading the launch parameters");
  }
  // The parameters of bounce b: the camera bounce's, then those reading queue 1 and queue 0 in turn.
  auto launch = [&](RaygenProgram program, uint32_t bounce, uint32_t launchWidth, uint32_t launchHeight) {
    const uint32_t set = bounce == 0 ? 0u : 2u - (bounce & 1u);
    checkOptix(optixLaunch(pipeline.get(), stream, parameters_[set].address(), sizeof p,
                           &pipeline.bindingTable(program), launchWidth, launchHeight, 1),
               "launching the device programs");
  };
  // After bounce b's shading, the length of the radiance queue of bounce b + 1 goes to the host, asynchronously;
  // radianceCount(b) waits for the length of bounce b's.
  auto copyRadianceCount = [&](uint32_t bounce) {
    const uint32_t copy = bounce % kCountCopies;
    checkCuda(cudaMemcpyAsync(hostCounts_ + copy, &counts[1 - (bounce & 1u)].radiance, sizeof(uint32_t),
                              cudaMemcpyDeviceToHost, stream),
              "reading a queue's length");
    checkCuda(cudaEventRecord(countsCopied_[copy], stream), "recording an event");
  };
  auto radianceCount = [&](uint32_t bounce) {
    const uint32_t copy = (bounce - 1) % kCountCopies;
    checkCuda(cudaEventSynchronize(countsCopied_[copy]), "running the device programs");
    return hostCounts_[copy];
  };
  checkCuda(cudaMemsetAsync(counts, 0, 2 * sizeof(QueueCounts), stream), "clearing the queues");
  // Launch sizes: a path queues at most one radiance ray and one shadow ray per bounce, so no queue of bounce b
  // is longer than bounce b - 1's radiance queue, whose length the host waits for while the GPU runs bounce b.
  // The GPU then never waits for the host between bounces; the launches' threads beyond their queue's length
  // return at once.
  // Bounce b's trace launch also traces the shadow rays of bounce b - 1. None are left after the loop: it ends
  // after a bounce that shaded no paths, after the bounce at the maximum depth, whose paths end before next-event
  // estimation (kernel/path_vertex.h's shadeVertex), or with the launch that follows the paths left to their ends.
  // The camera bounce's launches cover the pixels (two-dimensional, no queue).
  uint32_t bound = uint32_t(slots);
  for (uint32_t bounce = 0; bounce <= maxDepth && bound > 0; ++bounce) {
    const uint32_t next = 1 - (bounce & 1u);
    checkCuda(cudaMemsetAsync(counts + next, 0, sizeof(QueueCounts), stream), "clearing the queues");
    const uint32_t launchWidth = bounce == 0 ? width : bound, launchHeight = bounce == 0 ? rows : 1;
    launch(RaygenProgram::PathTrace, bounce, launchWidth, launchHeight);
    if (bounce > 0 && bound <= tailPaths_) {
      launch(RaygenProgram::PathTail, bounce, launchWidth, launchHeight);
      break;
    }
    launch(RaygenProgram::PathShade, bounce, launchWidth, launchHeight);
    copyRadianceCount(bounce);
    if (bounce >= 1) bound = radianceCount(bounce);
  }
  launch(RaygenProgram::PathFinish, 0, width, rows);
}

}  // namespace candela::optix
