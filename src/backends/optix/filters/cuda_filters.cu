#include "backends/optix/filters/cuda_filters.h"

#include "backends/optix/optix_error.h"
#include "image/filters/atrous_kernel.h"
#include "image/filters/bilateral_kernel.h"

namespace candela::optix {

namespace {

constexpr int kPlaneCount = 15;  // r, g, b, luminance twice; inverse colour width; nx, ny, nz, z, gx, gy
const dim3 kBlock(16, 16);

dim3 gridFor(uint32_t width, uint32_t height) {
  return dim3((width + kBlock.x - 1) / kBlock.x, (height + kBlock.y - 1) / kBlock.y);
}

struct Planes {
  float* r[2];
  float* g[2];
  float* b[2];
  float* lum[2];
  float* inverseWidth;
  float *nx, *ny, *nz, *z, *gx, *gy;
};

Planes planesOf(float* base, size_t pixels) {
  Planes p;
  float* next = base;
  auto take = [&] {
    float* plane = next;
    next += pixels;
    return plane;
  };
  for (int i = 0; i < 2; ++i) {
    p.r[i] = take();
    p.g[i] = take();
    p.b[i] = take();
    p.lum[i] = take();
  }
  p.inverseWidth = take();
  p.nx = take();
  p.ny = take();
  p.nz = take();
  p.z = take();
  p.gx = take();
  p.gy = take();
  return p;
}

__device__ float filmDepth(const DeviceFilmView& film, int x, int y, int w, int h) {
  return x < 0 || y < 0 || x >= w || y >= h ? 0.0f : film.depth[size_t(y) * w + x] * film.scale;
}

// Demodulates the colour and fills the guide planes, as atrous.cpp does; sums the demodulated luminance.
__global__ void prepareKernel(DeviceFilmView film, Planes p, int w, int h, double* luminanceSum) {
  const int x = int(blockIdx.x * blockDim.x + threadIdx.x), y = int(blockIdx.y * blockDim.y + threadIdx.y);
  double lum = 0.0;
  if (x < w && y < h) {
    const size_t i = size_t(y) * w + x;
    const Vec3 c = film.color[i] * film.scale, albedo = film.albedo[i] * film.scale;
    const float r = c.x / demodulationFactor(albedo.x), g = c.y / demodulationFactor(albedo.y),
                b = c.z / demodulationFactor(albedo.z);
    p.r[0][i] = r;
    p.g[0][i] = g;
    p.b[0][i] = b;
    lum = luminance({r, g, b});
    p.lum[0][i] = float(lum);
    const Vec3 n = unitOrZero(film.normal[i] * film.scale);
    p.nx[i] = n.x;
    p.ny[i] = n.y;
    p.nz[i] = n.z;
    const float z = filmDepth(film, x, y, w, h);
    p.z[i] = z;
    p.gx[i] = depthSlope(filmDepth(film, x - 1, y, w, h), z, filmDepth(film, x + 1, y, w, h));
    p.gy[i] = depthSlope(filmDepth(film, x, y - 1, w, h), z, filmDepth(film, x, y + 1, w, h));
  }
  for (int offset = 16; offset > 0; offset /= 2) lum += __shfl_down_sync(0xFFFFFFFFu, lum, offset);
  if ((threadIdx.y * blockDim.x + threadIdx.x) % 32 == 0) atomicAdd(luminanceSum, lum);
}

__global__ void colorWidthKernel(Planes p, int from, int w, int h, float colorSigma, const double* luminanceSum) {
  const int x = int(blockIdx.x * blockDim.x + threadIdx.x), y = int(blockIdx.y * blockDim.y + threadIdx.y);
  if (x >= w || y >= h) return;
  const float mean = float(*luminanceSum / double(size_t(w) * h));
  p.inverseWidth[size_t(y) * w + x] =
      atrousInverseColorWidth(localLuminanceVariance(p.lum[from], w, h, x, y), colorSigma, mean);
}

__global__ void atrousPassKernel(Planes p, int from, int w, int h, AtrousPassConstants k) {
  const int x = int(blockIdx.x * blockDim.x + threadIdx.x), y = int(blockIdx.y * blockDim.y + threadIdx.y);
  if (x >= w || y >= h) return;
  const float *inR = p.r[from], *inG = p.g[from], *inB = p.b[from];
  const size_t i = size_t(y) * w + x;
  const AtrousCentre centre{p.lum[from][i], p.inverseWidth[i], p.nx[i], p.ny[i], p.nz[i], p.z[i], p.gx[i], p.gy[i]};
  float sr = 0.0f, sg = 0.0f, sb = 0.0f, sw = 0.0f;
  for (int dy = -2; dy <= 2; ++dy) {
    const int qy = y + dy * k.step;
    if (qy < 0 || qy >= h) continue;
    for (int dx = -2; dx <= 2; ++dx) {
      const int qx = x + dx * k.step;
      if (qx < 0 || qx >= w) continue;
      const size_t q = size_t(qy) * w + qx;
      const float kernelWeight = b3Weight(dx) * b3Weight(dy);
      const float weight = atrousWeight(dx, dy, kernelWeight, k, centre, p.lum[from][q], p.nx[q], p.ny[q], p.nz[q], p.z[q]);
      sr += inR[q] * weight;
      sg += inG[q] * weight;
      sb += inB[q] * weight;
      sw += weight;
    }
  }
  const Vec3 out = Vec3{sr, sg, sb} / sw;
  p.r[1 - from][i] = out.x;
  p.g[1 - from][i] = out.y;
  p.b[1 - from][i] = out.z;
  p.lum[1 - from][i] = luminance(out);
}

__global__ void remodulateKernel(DeviceFilmView film, Planes p, int from, int w, int h, Vec3* output) {
  const int x = int(blockIdx.x * blockDim.x + threadIdx.x), y = int(blockIdx.y * blockDim.y + threadIdx.y);
  if (x >= w || y >= h) return;
  const size_t i = size_t(y) * w + x;
  const Vec3 albedo = film.albedo[i] * film.scale;
  output[i] = {p.r[from][i] * demodulationFactor(albedo.x), p.g[from][i] * demodulationFactor(albedo.y),
               p.b[from][i] * demodulationFactor(albedo.z)};
}

__global__ void bilateralKernel(const Vec3* input, float scale, Vec3* output, int w, int h, int r,
                                BilateralScales scales) {
  const int x = int(blockIdx.x * blockDim.x + threadIdx.x), y = int(blockIdx.y * blockDim.y + threadIdx.y);
  if (x >= w || y >= h) return;
  const Vec3 p = input[size_t(y) * w + x] * scale;
  float sr = 0.0f, sg = 0.0f, sb = 0.0f, sw = 0.0f;
  for (int dy = -r; dy <= r; ++dy) {
    if (y + dy < 0 || y + dy >= h) continue;
    for (int dx = -r; dx <= r; ++dx) {
      if (x + dx < 0 || x + dx >= w) continue;
      const Vec3 q = input[size_t(y + dy) * w + x + dx] * scale;
      const float weight = bilateralWeight(dx, dy, p.x, p.y, p.z, q.x, q.y, q.z, scales);
      sr += q.x * weight;
      sg += q.y * weight;
      sb += q.z * weight;
      sw += weight;
    }
  }
  output[size_t(y) * w + x] = Vec3{sr, sg, sb} / sw;
}

}  // namespace

CudaAtrous::CudaAtrous(uint32_t width, uint32_t height)
    : width_(width),
      height_(height),
      planes_(size_t(kPlaneCount) * width * height * sizeof(float), "the a-trous filter's planes"),
      luminanceSum_(sizeof(double), "the a-trous filter's luminance sum") {}

void CudaAtrous::run(const DeviceFilmView& film, Vec3* output, const AtrousParams& params, cudaStream_t stream) {
  const int w = int(width_), h = int(height_);
  const Planes p = planesOf(planes_.as<float>(), size_t(width_) * height_);
  const dim3 grid = gridFor(width_, height_);
  double* sum = luminanceSum_.as<double>();
  checkCuda(cudaMemsetAsync(sum, 0, sizeof(double), stream), "clearing the a-trous luminance sum");
  prepareKernel<<<grid, kBlock, 0, stream>>>(film, p, w, h, sum);
  int from = 0;
  for (int pass = 0; pass < params.passes; ++pass, from = 1 - from) {
    colorWidthKernel<<<grid, kBlock, 0, stream>>>(p, from, w, h, params.colorSigma, sum);
    atrousPassKernel<<<grid, kBlock, 0, stream>>>(p, from, w, h, atrousPassConstants(params, pass));
  }
  remodulateKernel<<<grid, kBlock, 0, stream>>>(film, p, from, w, h, output);
  checkCuda(cudaGetLastError(), "launching the a-trous filter");
}

void cudaBilateral(const Vec3* input, float scale, Vec3* output, uint32_t width, uint32_t height,
                   const BilateralParams& params, cudaStream_t stream) {
  bilateralKernel<<<gridFor(width, height), kBlock, 0, stream>>>(input, scale, output, int(width), int(height),
                                                                 params.radius, bilateralScales(params));
  checkCuda(cudaGetLastError(), "launching the bilateral filter");
}

Image atrousDenoiseCuda(const Image& color, const AovImages& aovs, const AtrousParams& params) {
  validateAtrousInput(color, aovs, params);
  DeviceBuffer c = DeviceBuffer::fromVector(color.pixels, "the image to filter");
  DeviceBuffer albedo = DeviceBuffer::fromVector(aovs.albedo.pixels, "the albedo AOV");
  DeviceBuffer normal = DeviceBuffer::fromVector(aovs.normal.pixels, "the normal AOV");
  DeviceBuffer depth = DeviceBuffer::fromVector(aovs.depth, "the depth AOV");
  DeviceBuffer out(c.size(), "the filtered image");
  CudaAtrous filter(color.width, color.height);
  filter.run({c.as<Vec3>(), albedo.as<Vec3>(), normal.as<Vec3>(), depth.as<float>(), 1.0f}, out.as<Vec3>(), params,
             nullptr);
  checkCuda(cudaStreamSynchronize(nullptr), "running the a-trous filter");
  Image result(color.width, color.height);
  out.download(result.pixels.data(), out.size());
  return result;
}

Image bilateralFilterCuda(const Image& input, const BilateralParams& params) {
  validateBilateralParams(params);
  DeviceBuffer in = DeviceBuffer::fromVector(input.pixels, "the image to filter");
  DeviceBuffer out(in.size(), "the filtered image");
  cudaBilateral(in.as<Vec3>(), 1.0f, out.as<Vec3>(), input.width, input.height, params, nullptr);
  checkCuda(cudaStreamSynchronize(nullptr), "running the bilateral filter");
  Image result(input.width, input.height);
  out.download(result.pixels.data(), out.size());
  return result;
}

}  // namespace candela::optix
