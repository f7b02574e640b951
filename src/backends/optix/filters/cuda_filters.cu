#include "backends/optix/filters/cuda_filters.h"

#include "backends/optix/filters/cuda_atrous_passes.h"
#include "backends/optix/optix_error.h"
#include "image/filters/bilateral_kernel.h"

namespace candela::optix {

namespace {

// What the filter smooths, as atrous.cpp does: first the demodulated reflected light, then the emission.
enum class Signal { Reflected, Emission };

// Fills the colour planes with the signal, and with the reflected light also the guide planes; sums the colour's
// luminance.
__global__ void prepareKernel(FilmView film, AtrousPlanes p, int w, int h, Signal signal, double* luminanceSum) {
  const int x = int(blockIdx.x * blockDim.x + threadIdx.x), y = int(blockIdx.y * blockDim.y + threadIdx.y);
  double lum = 0.0;
  if (x < w && y < h) {
    const size_t i = size_t(y) * w + x;
    const Vec3 emission = meanAt(film.emission, film.samples, i);
    const Vec3 c = signal == Signal::Emission ? filterableEmission(emission)
                                              : demodulate(meanAt(film.radiance, film.samples, i), emission,
                                                           meanAt(film.albedo, film.samples, i));
    lum = setSignal(p, x, y, w, c);
    if (signal == Signal::Reflected) writeAtrousGuides(film, p, x, y, w, h);
  }
  addToLuminanceSum(lum, luminanceSum);
}

__global__ void remodulateKernel(FilmView film, AtrousPlanes p, int from, int w, int h, Vec3* output) {
  const int x = int(blockIdx.x * blockDim.x + threadIdx.x), y = int(blockIdx.y * blockDim.y + threadIdx.y);
  if (x >= w || y >= h) return;
  const size_t i = size_t(y) * w + x;
  output[i] = remodulate({p.r[from][i], p.g[from][i], p.b[from][i]}, meanAt(film.albedo, film.samples, i));
}

// The variance of each pixel's mean for the mix with the raw pixel (stratifiedVariance), into `variance`: from the
// film's sums, or for images of means from `imageVariance` and `imageHalvesVariance`.
__global__ void stratifiedVarianceKernel(FilmView film, const float* imageVariance, const float* imageHalvesVariance,
                                         int w, int h, float* variance) {
  const int x = int(blockIdx.x * blockDim.x + threadIdx.x), y = int(blockIdx.y * blockDim.y + threadIdx.y);
  if (x >= w || y >= h) return;
  auto boundAt = [&](int qx, int qy) {
    const size_t q = size_t(qy) * w + qx;
    return film.samples ? meanLuminanceVariance(film.radiance[q], film.luminanceSquares[q], film.samples[q])
                        : imageVariance[q];
  };
  auto halvesAt = [&](int qx, int qy) {
    const size_t q = size_t(qy) * w + qx;
    return film.samples ? halvesVariance(film.radiance[q], film.oddLuminance[q], film.samples[q], film.oddSamples[q])
                        : imageHalvesVariance[q];
  };
  variance[size_t(y) * w + x] = stratifiedVariance(boundAt, halvesAt, w, h, x, y);
}

// Adds the filtered emission to the remodulated reflected light in `output` and mixes the sum with the raw pixel
// (blendWithRaw) by the variances stratifiedVarianceKernel wrote.
__global__ void finishKernel(FilmView film, const float* variance, AtrousPlanes p, int from, int w, int h,
                             Vec3* output) {
  const int x = int(blockIdx.x * blockDim.x + threadIdx.x), y = int(blockIdx.y * blockDim.y + threadIdx.y);
  if (x >= w || y >= h) return;
  const size_t i = size_t(y) * w + x;
  auto varianceAt = [&](int qx, int qy) { return variance[size_t(qy) * w + qx]; };
  const Vec3 emission{p.r[from][i], p.g[from][i], p.b[from][i]};
  output[i] =
      blendWithRaw(meanAt(film.radiance, film.samples, i), output[i] + emission, blendVariance(varianceAt, w, h, x, y));
}

// What the bilateral filter smooths at pixel i: the mean radiance without the emission, where the film has one.
__device__ Vec3 bilateralInput(const FilmView& film, size_t i) {
  const Vec3 c = meanAt(film.radiance, film.samples, i);
  return film.emission ? bilateralReflected(c, meanAt(film.emission, film.samples, i)) : bilateralInput(c);
}

__global__ void bilateralKernel(FilmView film, Vec3* output, int w, int h, int r, BilateralScales scales) {
  const int x = int(blockIdx.x * blockDim.x + threadIdx.x), y = int(blockIdx.y * blockDim.y + threadIdx.y);
  if (x >= w || y >= h) return;
  const size_t i = size_t(y) * w + x;
  const Vec3 p = bilateralInput(film, i);
  float sr = 0.0f, sg = 0.0f, sb = 0.0f, sw = 0.0f;
  for (int dy = -r; dy <= r; ++dy) {
    if (y + dy < 0 || y + dy >= h) continue;
    for (int dx = -r; dx <= r; ++dx) {
      if (x + dx < 0 || x + dx >= w) continue;
      const Vec3 q = bilateralInput(film, size_t(y + dy) * w + x + dx);
      const float weight = bilateralWeight(dx, dy, p.x, p.y, p.z, q.x, q.y, q.z, scales);
      sr += q.x * weight;
      sg += q.y * weight;
      sb += q.z * weight;
      sw += weight;
    }
  }
  const Vec3 filtered = Vec3{sr, sg, sb} / sw;
  output[i] = film.emission ? filtered + meanAt(film.emission, film.samples, i) : filtered;
}

__global__ void meansKernel(const Vec3* sums, const uint32_t* samples, Vec3* means, size_t pixels) {
  const size_t i = size_t(blockIdx.x) * blockDim.x + threadIdx.x;
  if (i < pixels) means[i] = meanAt(sums, samples, i);
}

}  // namespace

CudaAtrous::CudaAtrous(uint32_t width, uint32_t height)
    : width_(width),
      height_(height),
      planes_(atrousPlanesBytes(width, height), "the a-trous filter's planes"),
      luminanceSum_(sizeof(double), "the a-trous filter's luminance sum") {}

void CudaAtrous::run(const FilmView& film, const float* imageVariance, const float* imageHalvesVariance, Vec3* output,
                     const AtrousParams& params, cudaStream_t stream) {
  const int w = int(width_), h = int(height_);
  const AtrousPlanes p = atrousPlanesOf(planes_.as<void>(), width_, height_);
  const dim3 grid = filterGridFor(width_, height_);
  double* sum = luminanceSum_.as<double>();
  // Runs the passes on the signal; returns the colour planes that hold the result.
  auto filter = [&](Signal signal) {
    checkCuda(cudaMemsetAsync(sum, 0, sizeof(double), stream), "clearing the a-trous luminance sum");
    clearNonZeroRows(p, h, stream);
    prepareKernel<<<grid, kFilterBlock, 0, stream>>>(film, p, w, h, signal, sum);
    return enqueueAtrousPasses(p, w, h, params, sum, nullptr, nullptr, stream);
  };
  int from = filter(Signal::Reflected);
  remodulateKernel<<<grid, kFilterBlock, 0, stream>>>(film, p, from, w, h, output);
  from = filter(Signal::Emission);
  // The passes are done with the colour widths' plane.
  stratifiedVarianceKernel<<<grid, kFilterBlock, 0, stream>>>(film, imageVariance, imageHalvesVariance, w, h,
                                                              p.inverseWidth);
  finishKernel<<<grid, kFilterBlock, 0, stream>>>(film, p.inverseWidth, p, from, w, h, output);
  checkCuda(cudaGetLastError(), "launching the a-trous filter");
}

void cudaBilateral(const FilmView& film, Vec3* output, uint32_t width, uint32_t height, const BilateralParams& params,
                   cudaStream_t stream) {
  bilateralKernel<<<filterGridFor(width, height), kFilterBlock, 0, stream>>>(film, output, int(width), int(height),
                                                                             params.radius, bilateralScales(params));
  checkCuda(cudaGetLastError(), "launching the bilateral filter");
}

void cudaMeans(const Vec3* sums, const uint32_t* samples, Vec3* means, size_t pixels, cudaStream_t stream) {
  constexpr unsigned kBlock = 256;
  meansKernel<<<unsigned((pixels + kBlock - 1) / kBlock), kBlock, 0, stream>>>(sums, samples, means, pixels);
  checkCuda(cudaGetLastError(), "launching the means of a film channel");
}

Image atrousDenoiseCuda(const Image& color, const AovImages& aovs, const AtrousParams& params) {
  validateAtrousInput(color, aovs, params);
  DeviceBuffer c = DeviceBuffer::fromVector(color.pixels, "the image to filter");
  DeviceBuffer albedo = DeviceBuffer::fromVector(aovs.albedo.pixels, "the albedo AOV");
  DeviceBuffer normal = DeviceBuffer::fromVector(aovs.normal.pixels, "the normal AOV");
  DeviceBuffer depth = DeviceBuffer::fromVector(aovs.depth, "the depth AOV");
  DeviceBuffer emission = DeviceBuffer::fromVector(aovs.emission.pixels, "the emission image");
  DeviceBuffer variance = DeviceBuffer::fromVector(aovs.variance, "the variance AOV");
  DeviceBuffer halves = DeviceBuffer::fromVector(aovs.halvesVariance, "the halves' variance AOV");
  DeviceBuffer out(c.size(), "the filtered image");
  CudaAtrous filter(color.width, color.height);
  FilmView film;  // images of means: no sample counts
  film.radiance = c.as<Vec3>();
  film.emission = emission.as<Vec3>();
  film.albedo = albedo.as<Vec3>();
  film.normal = normal.as<Vec3>();
  film.depth = depth.as<float>();
  filter.run(film, variance.as<float>(), halves.as<float>(), out.as<Vec3>(), params, nullptr);
  checkCuda(cudaStreamSynchronize(nullptr), "running the a-trous filter");
  Image result(color.width, color.height);
  out.download(result.pixels.data(), out.size());
  return result;
}

Image bilateralFilterCuda(const Image& input, const BilateralParams& params) {
  validateBilateralParams(params);
  DeviceBuffer in = DeviceBuffer::fromVector(input.pixels, "the image to filter");
  DeviceBuffer out(in.size(), "the filtered image");
  FilmView image;  // an image of means, with no emission
  image.radiance = in.as<Vec3>();
  cudaBilateral(image, out.as<Vec3>(), input.width, input.height, params, nullptr);
  checkCuda(cudaStreamSynchronize(nullptr), "running the bilateral filter");
  Image result(input.width, input.height);
  out.download(result.pixels.data(), out.size());
  return result;
}

}  // namespace candela::optix
