#include "backends/optix/filters/cuda_temporal.h"

#include "backends/optix/filters/cuda_atrous_passes.h"
#include "backends/optix/optix_error.h"
#include "image/filters/temporal_kernel.h"

namespace candela::optix {

namespace {

// A history's planes (TemporalFilter::History) in one allocation.
struct HistoryPlanes {
  Vec3 *reflected, *emission, *normal;
  float *length, *moment1, *moment2, *depth;
  uint8_t* emissive;
};

constexpr size_t kHistoryBytesPerPixel = 3 * sizeof(Vec3) + 4 * sizeof(float) + sizeof(uint8_t);

HistoryPlanes historyPlanesOf(void* base, size_t pixels) {
  char* next = static_cast<char*>(base);
  auto take = [&](size_t bytesPerPixel) {
    char* plane = next;
    next += bytesPerPixel * pixels;
    return plane;
  };
  HistoryPlanes p;
  p.reflected = reinterpret_cast<Vec3*>(take(sizeof(Vec3)));
  p.emission = reinterpret_cast<Vec3*>(take(sizeof(Vec3)));
  p.normal = reinterpret_cast<Vec3*>(take(sizeof(Vec3)));
  p.length = reinterpret_cast<float*>(take(sizeof(float)));
  p.moment1 = reinterpret_cast<float*>(take(sizeof(float)));
  p.moment2 = reinterpret_cast<float*>(take(sizeof(float)));
  p.depth = reinterpret_cast<float*>(take(sizeof(float)));
  p.emissive = reinterpret_cast<uint8_t*>(take(sizeof(uint8_t)));
  return p;
}

// The guides of the a-trous passes, whose unit normals and depths the reprojection and the new history take too: each
// pixel's normal is made unit once (as TemporalFilter::filter takes AtrousWorkspace::unitNormals).
__global__ void guidesKernel(FilmView film, AtrousPlanes p, int w, int h) {
  const int x = int(blockIdx.x * blockDim.x + threadIdx.x), y = int(blockIdx.y * blockDim.y + threadIdx.y);
  if (x < w && y < h) writeAtrousGuides(film, p, x, y, w, h);
}

// The last frame's history reprojected to the current film's pixels (guided by guidesKernel's planes), into `base`.
__global__ void reprojectKernel(FilmView film, AtrousPlanes p, HistoryPlanes last, HistoryPlanes base, Camera current,
                                Camera previous, int w, int h, TemporalLimits limits) {
  const int x = int(blockIdx.x * blockDim.x + threadIdx.x), y = int(blockIdx.y * blockDim.y + threadIdx.y);
  if (x >= w || y >= h) return;
  const size_t i = size_t(y) * w + x;
  auto historyAt = [&](int qx, int qy, TemporalGuides& guides) {
    const size_t q = size_t(qy) * w + qx;
    guides = {last.normal[q], last.depth[q], last.emissive[q] != 0};
    return TemporalSample{last.reflected[q], last.emission[q], last.length[q], last.moment1[q], last.moment2[q]};
  };
  const TemporalGuides guides{unitNormalAt(p, i), p.z[i], isEmissive(meanAt(film.emission, film.samples, i))};
  const TemporalSample s = reprojectHistory(current, previous, w, h, x, y, guides, limits, historyAt);
  base.reflected[i] = s.reflected;
  base.emission[i] = s.emission;
  base.length[i] = s.length;
  base.moment1[i] = s.moment1;
  base.moment2[i] = s.moment2;
}

// The film added to the history `base`: the accumulated reflected light into colour planes 0 (and its luminance
// summed), the first pass's variance, and the new history's planes other than the reflected light (which the first
// a-trous pass gives), its normals and depths from guidesKernel's planes.
__global__ void accumulateKernel(FilmView film, HistoryPlanes base, HistoryPlanes last, AtrousPlanes p, float* variance,
                                 int w, int h, float samples, double* luminanceSum) {
  const int x = int(blockIdx.x * blockDim.x + threadIdx.x), y = int(blockIdx.y * blockDim.y + threadIdx.y);
  double lum = 0.0;
  if (x < w && y < h) {
    const size_t i = size_t(y) * w + x;
    const Vec3 emission = meanAt(film.emission, film.samples, i);
    const TemporalSample b{base.reflected[i], base.emission[i], base.length[i], base.moment1[i], base.moment2[i]};
    const TemporalSample s = accumulateTemporal(
        b, demodulate(meanAt(film.radiance, film.samples, i), emission, meanAt(film.albedo, film.samples, i)),
        filterableEmission(emission), samples);
    lum = setSignal(p, x, y, w, s.reflected);
    variance[i] = temporalVariance(s, samples);
    last.emission[i] = s.emission;
    last.length[i] = s.length;
    last.moment1[i] = s.moment1;
    last.moment2[i] = s.moment2;
    last.normal[i] = unitNormalAt(p, i);
    last.depth[i] = p.z[i];
    last.emissive[i] = isEmissive(s.emission) ? 1 : 0;
  }
  addToLuminanceSum(lum, luminanceSum);
}

// The filtered reflected light remodulated, into `output`.
__global__ void remodulateKernel(FilmView film, AtrousPlanes p, int from, int w, int h, Vec3* output) {
  const int x = int(blockIdx.x * blockDim.x + threadIdx.x), y = int(blockIdx.y * blockDim.y + threadIdx.y);
  if (x >= w || y >= h) return;
  const size_t i = size_t(y) * w + x;
  output[i] = remodulate({p.r[from][i], p.g[from][i], p.b[from][i]}, meanAt(film.albedo, film.samples, i));
}

// The accumulated emission into colour planes 0, its luminance summed.
__global__ void emissionKernel(const Vec3* emission, AtrousPlanes p, int w, int h, double* luminanceSum) {
  const int x = int(blockIdx.x * blockDim.x + threadIdx.x), y = int(blockIdx.y * blockDim.y + threadIdx.y);
  double lum = 0.0;
  if (x < w && y < h) {
    lum = setSignal(p, x, y, w, emission[size_t(y) * w + x]);
  }
  addToLuminanceSum(lum, luminanceSum);
}

// The filtered emission added to the remodulated reflected light in `output`.
__global__ void addEmissionKernel(AtrousPlanes p, int from, int w, int h, Vec3* output) {
  const int x = int(blockIdx.x * blockDim.x + threadIdx.x), y = int(blockIdx.y * blockDim.y + threadIdx.y);
  if (x >= w || y >= h) return;
  const size_t i = size_t(y) * w + x;
  output[i] = output[i] + Vec3{p.r[from][i], p.g[from][i], p.b[from][i]};
}

}  // namespace

CudaTemporal::CudaTemporal(TemporalParams params) : params_(params) { validateTemporalParams(params_); }

void CudaTemporal::reset() {
  haveHistory_ = false;
  width_ = height_ = 0;
}

void CudaTemporal::resize(uint32_t width, uint32_t height, cudaStream_t stream) {
  const size_t pixels = size_t(width) * height;
  width_ = width;
  height_ = height;
  haveHistory_ = false;
  if (planes_.size() != atrousPlanesBytes(width, height)) {
    // The old buffers freed before the new ones are made.
    base_ = DeviceBuffer();
    last_ = DeviceBuffer();
    planes_ = DeviceBuffer();
    variance_ = DeviceBuffer();
    base_ = DeviceBuffer(kHistoryBytesPerPixel * pixels, "the temporal filter's history");
    last_ = DeviceBuffer(kHistoryBytesPerPixel * pixels, "the temporal filter's history");
    planes_ = DeviceBuffer(atrousPlanesBytes(width, height), "the temporal filter's planes");
    variance_ = DeviceBuffer(pixels * sizeof(float), "the temporal filter's variances");
  }
  if (sums_.size() == 0) sums_ = DeviceBuffer(2 * sizeof(double), "the temporal filter's luminance sums");
  // No history: every length zero (TemporalFilter::History::resize).
  checkCuda(cudaMemsetAsync(base_.as<void>(), 0, base_.size(), stream), "clearing the temporal filter's history");
  checkCuda(cudaMemsetAsync(last_.as<void>(), 0, last_.size(), stream), "clearing the temporal filter's history");
}

void CudaTemporal::run(const FilmView& film, uint32_t width, uint32_t height, const Camera& camera, uint32_t samples,
                       bool filmContinues, Vec3* output, cudaStream_t stream) {
  if (width != width_ || height != height_) resize(width, height, stream);
  const int w = int(width), h = int(height);
  const size_t pixels = size_t(width) * height;
  const dim3 grid = filterGridFor(width, height);
  const HistoryPlanes base = historyPlanesOf(base_.as<void>(), pixels),
                      last = historyPlanesOf(last_.as<void>(), pixels);
  const AtrousPlanes p = atrousPlanesOf(planes_.as<void>(), width, height);
  const TemporalLimits limits{params_.maxHistory, params_.depthTolerance, params_.normalTolerance};

  guidesKernel<<<grid, kFilterBlock, 0, stream>>>(film, p, w, h);

  // The history this film starts from: the last frame's reprojected, unless the film goes on from that frame's.
  if (!filmContinues) {
    if (haveHistory_)
      reprojectKernel<<<grid, kFilterBlock, 0, stream>>>(film, p, last, base, camera, camera_, w, h, limits);
    else
      checkCuda(cudaMemsetAsync(base_.as<void>(), 0, base_.size(), stream), "clearing the temporal filter's history");
  }

  // The film added to it; the reflected light goes through the a-trous passes, whose first level is the next history.
  double* sums = sums_.as<double>();
  checkCuda(cudaMemsetAsync(sums, 0, 2 * sizeof(double), stream), "clearing the temporal filter's sums");
  const float samplesPerPixel = float(samples > 0 ? samples : 1);
  clearNonZeroRows(p, h, stream);
  accumulateKernel<<<grid, kFilterBlock, 0, stream>>>(film, base, last, p, variance_.as<float>(), w, h, samplesPerPixel,
                                                      sums);
  int from = enqueueAtrousPasses(p, w, h, params_.atrous, sums, variance_.as<float>(), last.reflected, stream);
  remodulateKernel<<<grid, kFilterBlock, 0, stream>>>(film, p, from, w, h, output);
  camera_ = camera;
  haveHistory_ = true;

  // The accumulated emission through passes of its own.
  clearNonZeroRows(p, h, stream);
  emissionKernel<<<grid, kFilterBlock, 0, stream>>>(last.emission, p, w, h, sums + 1);
  from = enqueueAtrousPasses(p, w, h, params_.atrous, sums + 1, nullptr, nullptr, stream);
  addEmissionKernel<<<grid, kFilterBlock, 0, stream>>>(p, from, w, h, output);
  checkCuda(cudaGetLastError(), "launching the temporal filter");
}

}  // namespace candela::optix
