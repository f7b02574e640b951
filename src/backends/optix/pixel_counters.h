#pragma once
// Sums the per-pixel counters of one launch on the device, so that only two numbers come back to the host.
#include <cuda_runtime.h>

#include <cstdint>

#include "backends/optix/launch_params.h"

namespace candela::optix {

struct CounterTotals {
  unsigned long long rays;
  unsigned long long invalidSamples;
};

// Enqueues on `stream`: totals = sum over the `count` counters. `totals` is device memory.
void sumPixelCounters(const PixelCounters* counters, uint32_t count, CounterTotals* totals, cudaStream_t stream);

}  // namespace candela::optix
