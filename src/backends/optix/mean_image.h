#pragma once
// The film's mean radiance (kernel/film.h) written to other device memory, for a consumer
// on the same GPU (the viewer's OpenGL pixel buffer) that should not wait for a copy through the host.
#include <cuda_runtime.h>

#include <cstdint>

#include "kernel/film.h"

namespace candela::optix {

// Enqueues on `stream`: mean[i] = the film's mean radiance at pixel i for the `count` pixels. The film and `mean`
// are device memory.
void writeMeanImage(const FilmView& film, uint32_t count, Vec3* mean, cudaStream_t stream);

}  // namespace candela::optix
