#pragma once
// Adding one film's sums to another's on the device: the films of several devices become one.
#include <cuda_runtime.h>

#include <cstdint>

#include "kernel/film.h"

namespace candela::optix {

// Enqueues on `stream`: every sum and count of `destination` += that of `source`, for the pixels
// [first, first + count); the AOV sums too where `withAovs`. Both films are memory of the current device.
void addFilmPixels(const FilmView& destination, const FilmView& source, uint32_t first, uint32_t count, bool withAovs,
                   cudaStream_t stream);

}  // namespace candela::optix
