#pragma once
// The film's mean (accumulated sums times 1 / sample count) written to other device memory, for a consumer
// on the same GPU (the viewer's OpenGL pixel buffer) that should not wait for a copy through the host.
#include <cuda_runtime.h>

#include <cstdint>

#include "core/math.h"

namespace candela::optix {

// Enqueues on `stream`: mean[i] = sum[i] * scale for the `count` pixels. Both pointers are device memory.
void writeMeanImage(const Vec3* sum, uint32_t count, float scale, Vec3* mean, cudaStream_t stream);

}  // namespace candela::optix
