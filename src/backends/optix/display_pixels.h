#pragma once
// The display frame of image/display_pixels.h in CUDA: the same per-pixel code (image/display_kernel.h), on linear
// radiance in device memory.
#include <cuda_runtime.h>

#include <cstdint>

#include "image/display_kernel.h"

namespace candela::optix {

// Enqueues on `stream` the display frame of `source` at `divisor` (displaySize's pixels, three bytes each) into
// `rgb`. The source's memory, `table` (a copy of srgbByteTable()) and `rgb` are device memory.
void enqueueDisplayPixels(const LinearPixels& source, uint32_t divisor, const DisplayMapping& mapping,
                          const SrgbByteTable* table, uint8_t* rgb, cudaStream_t stream);

}  // namespace candela::optix
