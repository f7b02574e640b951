#include "backends/optix/filters/cuda_atrous_passes.h"

#include "backends/optix/optix_error.h"

namespace candela::optix {

namespace {

// The colour widths of a pass from the luminance's neighbourhood, or from `variance` where it is given and not
// negative.
__global__ void colorWidthKernel(AtrousPlanes p, int from, int w, int h, float colorSigma, const double* luminanceSum,
                                 const float* variance) {
  const int x = int(blockIdx.x * blockDim.x + threadIdx.x), y = int(blockIdx.y * blockDim.y + threadIdx.y);
  if (x >= w || y >= h) return;
  const size_t i = size_t(y) * w + x;
  const float mean = float(*luminanceSum / double(size_t(w) * h));
  const float given = variance ? variance[i] : -1.0f;
  p.inverseWidth[i] = atrousInverseColorWidth(given >= 0.0f ? given : localLuminanceVariance(p.lum[from], w, h, x, y),
                                              colorSigma, mean);
}

__global__ void atrousPassKernel(AtrousPlanes p, int from, int w, int h, AtrousPassConstants k) {
  const int x = int(blockIdx.x * blockDim.x + threadIdx.x), y = int(blockIdx.y * blockDim.y + threadIdx.y);
  if (x >= w || y >= h) return;
  const float *inR = p.r[from], *inG = p.g[from], *inB = p.b[from];
  const size_t i = size_t(y) * w + x;
  bool anyTap = false;
  for (int dy = -2; dy <= 2; ++dy) {
    const int qy = y + dy * k.step;
    anyTap = anyTap || (qy >= 0 && qy < h && p.nonZeroRow[from][qy] != 0);
  }
  if (!anyTap) {  // every tap zero: so is the weighted mean
    p.r[1 - from][i] = p.g[1 - from][i] = p.b[1 - from][i] = p.lum[1 - from][i] = 0.0f;
    return;
  }
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
      const float weight =
          atrousWeight(dx, dy, kernelWeight, k, centre, p.lum[from][q], p.nx[q], p.ny[q], p.nz[q], p.z[q]);
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
  if (out.x != 0.0f || out.y != 0.0f || out.z != 0.0f) p.nonZeroRow[1 - from][y] = 1;
}

__global__ void copyLevelKernel(AtrousPlanes p, int from, int w, int h, Vec3* level) {
  const int x = int(blockIdx.x * blockDim.x + threadIdx.x), y = int(blockIdx.y * blockDim.y + threadIdx.y);
  if (x >= w || y >= h) return;
  const size_t i = size_t(y) * w + x;
  level[i] = {p.r[from][i], p.g[from][i], p.b[from][i]};
}

}  // namespace

constexpr int kPlaneCount = 15;  // r, g, b, luminance twice; inverse colour width; nx, ny, nz, z, gx, gy

size_t atrousPlanesBytes(uint32_t width, uint32_t height) {
  return size_t(kPlaneCount) * width * height * sizeof(float) + 2 * size_t(height) * sizeof(uint32_t);
}

AtrousPlanes atrousPlanesOf(void* base, uint32_t width, uint32_t height) {
  const size_t pixels = size_t(width) * height;
  AtrousPlanes p;
  float* next = static_cast<float*>(base);
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
  p.nonZeroRow[0] = reinterpret_cast<uint32_t*>(next);
  p.nonZeroRow[1] = p.nonZeroRow[0] + height;
  return p;
}

void clearNonZeroRows(const AtrousPlanes& p, int h, cudaStream_t stream) {
  checkCuda(cudaMemsetAsync(p.nonZeroRow[0], 0, size_t(h) * sizeof(uint32_t), stream), "clearing the row marks");
}

int enqueueAtrousPasses(const AtrousPlanes& p, int w, int h, const AtrousParams& params, const double* luminanceSum,
                        const float* firstPassVariance, Vec3* firstLevel, cudaStream_t stream) {
  const dim3 grid = filterGridFor(uint32_t(w), uint32_t(h));
  if (firstLevel && params.passes == 0) copyLevelKernel<<<grid, kFilterBlock, 0, stream>>>(p, 0, w, h, firstLevel);
  int from = 0;
  for (int pass = 0; pass < params.passes; ++pass, from = 1 - from) {
    checkCuda(cudaMemsetAsync(p.nonZeroRow[1 - from], 0, size_t(h) * sizeof(uint32_t), stream),
              "clearing the row marks");
    colorWidthKernel<<<grid, kFilterBlock, 0, stream>>>(p, from, w, h, params.colorSigma, luminanceSum,
                                                        pass == 0 ? firstPassVariance : nullptr);
    atrousPassKernel<<<grid, kFilterBlock, 0, stream>>>(p, from, w, h, atrousPassConstants(params, pass));
    if (pass == 0 && firstLevel) copyLevelKernel<<<grid, kFilterBlock, 0, stream>>>(p, 1, w, h, firstLevel);
  }
  checkCuda(cudaGetLastError(), "launching the a-trous passes");
  return from;
}

}  // namespace candela::optix
