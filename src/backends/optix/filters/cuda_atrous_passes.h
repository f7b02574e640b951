#pragma once
// The a-trous passes in CUDA, shared by the spatial filter (cuda_filters.cu) and the temporal one (cuda_temporal.cu):
// the guide and colour planes they work on, the guides' device-side preparation, and the passes themselves.
// Included only by CUDA sources.
#include <cuda_runtime.h>

#include "image/filters/atrous.h"
#include "image/filters/atrous_kernel.h"
#include "kernel/film.h"

namespace candela::optix {

const dim3 kFilterBlock(16, 16);

inline dim3 filterGridFor(uint32_t width, uint32_t height) {
  return dim3((width + kFilterBlock.x - 1) / kFilterBlock.x, (height + kFilterBlock.y - 1) / kFilterBlock.y);
}

// The planes, one float per pixel each, that the passes read and write: the colour and its luminance twice (the
// passes alternate between them), the colour widths of the current pass, and the guides; and per row of each colour
// plane, whether any of its pixels is not zero. A pass gives zero where all the taps are zero, so the rows far from
// any non-zero one are not filtered: the emission is zero in most rows of most images.
struct AtrousPlanes {
  float* r[2];
  float* g[2];
  float* b[2];
  float* lum[2];
  float* inverseWidth;
  float *nx, *ny, *nz, *z, *gx, *gy;
  uint32_t* nonZeroRow[2];
};

// The bytes of the planes of a width x height image.
size_t atrousPlanesBytes(uint32_t width, uint32_t height);
// The planes in atrousPlanesBytes(width, height) bytes from `base`.
AtrousPlanes atrousPlanesOf(void* base, uint32_t width, uint32_t height);

__device__ inline float filmDepth(const FilmView& film, int x, int y, int w, int h) {
  return x < 0 || y < 0 || x >= w || y >= h ? 0.0f : meanAt(film.depth, film.samples, size_t(y) * w + x);
}

// The guides of pixel (x, y) from the film's AOVs, as fillGuides in atrous.cpp makes them.
__device__ inline void writeAtrousGuides(const FilmView& film, const AtrousPlanes& p, int x, int y, int w, int h) {
  const size_t i = size_t(y) * w + x;
  const Vec3 n = unitOrZero(meanAt(film.normal, film.samples, i));
  p.nx[i] = n.x;
  p.ny[i] = n.y;
  p.nz[i] = n.z;
  const float z = filmDepth(film, x, y, w, h);
  p.z[i] = z;
  p.gx[i] = depthSlope(filmDepth(film, x - 1, y, w, h), z, filmDepth(film, x + 1, y, w, h));
  p.gy[i] = depthSlope(filmDepth(film, x, y - 1, w, h), z, filmDepth(film, x, y + 1, w, h));
}

// The unit normal (zero where the path escaped) of pixel i that writeAtrousGuides made of the film's.
__device__ inline Vec3 unitNormalAt(const AtrousPlanes& p, size_t i) { return {p.nx[i], p.ny[i], p.nz[i]}; }

// Adds the luminances of a block's threads to `sum` (one atomic per warp); every thread of the block calls it.
__device__ inline void addToLuminanceSum(double lum, double* sum) {
  for (int offset = 16; offset > 0; offset /= 2) lum += __shfl_down_sync(0xFFFFFFFFu, lum, offset);
  if ((threadIdx.y * blockDim.x + threadIdx.x) % 32 == 0) atomicAdd(sum, lum);
}

// Sets the colour of pixel (x, y) in colour planes 0 and its luminance (returned); marks its row where it is not zero.
// nonZeroRow[0] must have been cleared.
__device__ inline float setSignal(const AtrousPlanes& p, int x, int y, int w, Vec3 c) {
  const size_t i = size_t(y) * w + x;
  p.r[0][i] = c.x;
  p.g[0][i] = c.y;
  p.b[0][i] = c.z;
  const float lum = luminance(c);
  p.lum[0][i] = lum;
  if (c.x != 0.0f || c.y != 0.0f || c.z != 0.0f) p.nonZeroRow[0][y] = 1;
  return lum;
}

// Clears the row marks of colour planes 0, before the signal is set.
void clearNonZeroRows(const AtrousPlanes& p, int h, cudaStream_t stream);

// Enqueues params.passes passes over colour planes 0 (set with setSignal), guided by the guide planes,
// with the colour widths' floor from the mean luminance *luminanceSum / pixels. `firstPassVariance`, unless null,
// gives the first pass the variance of each pixel's luminance where it is not negative (atrousSmooth's). The first
// pass's output (the input for no passes) is copied to `firstLevel` unless it is null. Returns the index of the colour
// planes that hold the result.
int enqueueAtrousPasses(const AtrousPlanes& p, int w, int h, const AtrousParams& params, const double* luminanceSum,
                        const float* firstPassVariance, Vec3* firstLevel, cudaStream_t stream);

}  // namespace candela::optix
