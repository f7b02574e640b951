// Instantiates the shared kernel code for the device so that every build with nvcc proves it stays
// device-clean. The tracer here never hits anything; the OptiX backend supplies the real one.
#include "kernel/integrator.h"
#include "kernel/restir/restir_passes.h"

namespace candela {

struct MissEverythingTracer {
  __device__ bool intersect(const Ray&, Hit&, uint32_t) const { return false; }
  __device__ bool occluded(const Ray&, uint32_t) const { return false; }
};

__global__ void compileKernelForDevice(SceneView scene, Camera camera, RenderSettings settings, Vec3* out) {
  uint32_t x = blockIdx.x * blockDim.x + threadIdx.x, y = blockIdx.y * blockDim.y + threadIdx.y;
  if (x >= settings.width || y >= settings.height) return;
  PathResult r = renderPixelSample(scene, MissEverythingTracer{}, camera, settings, x, y, 0);
  out[y * settings.width + x] = r.radiance;
}

// The path through participating media (kernel/media/volume_path.h), with the denoisers' guides.
__global__ void compileMediaPathForDevice(SceneView scene, Camera camera, RenderSettings settings, Vec3* out) {
  uint32_t x = blockIdx.x * blockDim.x + threadIdx.x, y = blockIdx.y * blockDim.y + threadIdx.y;
  if (x >= settings.width || y >= settings.height) return;
  PathResult r = renderPixelSample<true, true>(scene, MissEverythingTracer{}, camera, settings, x, y, 0);
  out[y * settings.width + x] = r.radiance;
}

// ReSTIR DI's four passes (kernel/restir/restir_passes.h), each as one launch over the image would run it (the
// presampling with one thread per pixel, each presampling its pixel's light of its tile).
__global__ void compileRestirPrimaryForDevice(SceneView scene, Camera camera, RenderSettings settings,
                                              RestirView restir, uint32_t* rays) {
  uint32_t x = blockIdx.x * blockDim.x + threadIdx.x, y = blockIdx.y * blockDim.y + threadIdx.y;
  if (x >= settings.width || y >= settings.height) return;
  rays[y * settings.width + x] = restirPrimaryPass(scene, MissEverythingTracer{}, camera, settings, restir, x, y, 0);
}

__global__ void compileRestirPresamplingForDevice(SceneView scene, RenderSettings settings, RestirView restir) {
  uint32_t x = blockIdx.x * blockDim.x + threadIdx.x, y = blockIdx.y * blockDim.y + threadIdx.y;
  if (x >= settings.width || y >= settings.height) return;
  const uint32_t light = restirIndexInTile(settings, x, y);
  restirPresamplePass(scene, settings, restir, restirTileOf(settings, x, y), light, light + 1, 0);
}

__global__ void compileRestirCandidatesForDevice(SceneView scene, RenderSettings settings, RestirView restir,
                                                 uint32_t* rays) {
  uint32_t x = blockIdx.x * blockDim.x + threadIdx.x, y = blockIdx.y * blockDim.y + threadIdx.y;
  if (x >= settings.width || y >= settings.height) return;
  rays[y * settings.width + x] = restirCandidatePass(scene, MissEverythingTracer{}, settings, restir, x, y, 0);
}

__global__ void compileRestirShadingForDevice(SceneView scene, Camera camera, RenderSettings settings,
                                              RestirView restir, Vec3* out) {
  uint32_t x = blockIdx.x * blockDim.x + threadIdx.x, y = blockIdx.y * blockDim.y + threadIdx.y;
  if (x >= settings.width || y >= settings.height) return;
  PathResult r = restirShadePass<true>(scene, MissEverythingTracer{}, camera, settings, restir, x, y, 0);
  out[y * settings.width + x] = r.radiance;
}

}  // namespace candela
