// The CUDA filters (a-trous, temporal with a-trous, bilateral) at 1920x1080 on images already in device memory, timed
// with CUDA events: 20 untimed runs, then the median of 100. Prints one JSON line per filter.
#include <cuda_runtime.h>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <vector>

#include "backends/optix/filters/cuda_filters.h"
#include "backends/optix/filters/cuda_temporal.h"
#include "backends/optix/optix_error.h"
#include "filter_inputs.h"

using namespace candela;
using namespace candela::optix;

namespace {

double medianMilliseconds(cudaStream_t stream, const std::function<void()>& enqueue) {
  cudaEvent_t start, stop;
  checkCuda(cudaEventCreate(&start), "creating a CUDA event");
  checkCuda(cudaEventCreate(&stop), "creating a CUDA event");
  for (int i = 0; i < 20; ++i) enqueue();
  std::vector<double> times;
  for (int i = 0; i < 100; ++i) {
    checkCuda(cudaEventRecord(start, stream), "recording a CUDA event");
    enqueue();
    checkCuda(cudaEventRecord(stop, stream), "recording a CUDA event");
    checkCuda(cudaEventSynchronize(stop), "running a filter");
    float ms = 0.0f;
    checkCuda(cudaEventElapsedTime(&ms, start, stop), "reading a CUDA event");
    times.push_back(ms);
  }
  cudaEventDestroy(start);
  cudaEventDestroy(stop);
  std::sort(times.begin(), times.end());
  return 0.5 * (times[49] + times[50]);
}

}  // namespace

int main() {
  try {
    cudaDeviceProp properties{};
    checkCuda(cudaGetDeviceProperties(&properties, 0), "reading the GPU's properties");
    const bench::FilterInput in = bench::noisyFrame();
    const uint32_t w = in.color.width, h = in.color.height;
    DeviceBuffer color = DeviceBuffer::fromVector(in.color.pixels, "the image");
    DeviceBuffer albedo = DeviceBuffer::fromVector(in.aovs.albedo.pixels, "the albedo");
    DeviceBuffer normal = DeviceBuffer::fromVector(in.aovs.normal.pixels, "the normals");
    DeviceBuffer depth = DeviceBuffer::fromVector(in.aovs.depth, "the depth");
    DeviceBuffer emission = DeviceBuffer::fromVector(in.aovs.emission.pixels, "the emission");
    DeviceBuffer variance = DeviceBuffer::fromVector(in.aovs.variance, "the variance");
    DeviceBuffer halves = DeviceBuffer::fromVector(in.aovs.halvesVariance, "the halves' variance");
    DeviceBuffer out(color.size(), "the output");
    cudaStream_t stream;
    checkCuda(cudaStreamCreate(&stream), "creating a CUDA stream");
    CudaAtrous atrous(w, h);
    // Images of means: no sample counts.
    const FilmView film{.radiance = color.as<Vec3>(),
                        .emission = emission.as<Vec3>(),
                        .albedo = albedo.as<Vec3>(),
                        .normal = normal.as<Vec3>(),
                        .depth = depth.as<float>()};
    AtrousParams params;
    params.passes = 5;
    const double atrousMs = medianMilliseconds(stream, [&] {
      atrous.run(film, variance.as<float>(), halves.as<float>(), out.as<Vec3>(), params, stream);
    });
    // Reprojection, accumulation and the a-trous passes (reflected light and emission) of a frame whose camera moved
    // a little since the last, as the CPU benchmark's temporalAndAtrous.
    // With emitted light in a quarter of the rows, which the emission's passes do not skip.
    const bench::FilterInput sky = bench::withEmission(in, 25);
    DeviceBuffer skyColor = DeviceBuffer::fromVector(sky.color.pixels, "the image with emission");
    DeviceBuffer skyEmission = DeviceBuffer::fromVector(sky.aovs.emission.pixels, "the emission");
    FilmView skyFilm = film;
    skyFilm.radiance = skyColor.as<Vec3>();
    skyFilm.emission = skyEmission.as<Vec3>();
    CudaTemporal temporal;
    Camera camera = Camera::lookAt({0, 5, 0}, {0, 0, 0}, {0, 0, 1}, 40.0f, float(w) / float(h));
    temporal.run(skyFilm, w, h, camera, 1, false, out.as<Vec3>(), stream);
    const double temporalMs = medianMilliseconds(stream, [&] {
      camera.position.x += 1e-4f;
      temporal.run(skyFilm, w, h, camera, 1, false, out.as<Vec3>(), stream);
    });
    const double bilateralMs =
        medianMilliseconds(stream, [&] { cudaBilateral(film, out.as<Vec3>(), w, h, BilateralParams{}, stream); });
    std::printf(
        "{\"filter\":\"atrous\",\"passes\":5,\"width\":%u,\"height\":%u,\"device\":\"%s\",\"median_ms\":%.4f}\n", w, h,
        properties.name, atrousMs);
    std::printf(
        "{\"filter\":\"temporal\",\"passes\":5,\"emitting_rows_percent\":25,\"width\":%u,\"height\":%u,\"device\":\"%"
        "s\",\"median_ms\":%.4f}\n",
        w, h, properties.name, temporalMs);
    std::printf(
        "{\"filter\":\"bilateral\",\"radius\":3,\"width\":%u,\"height\":%u,\"device\":\"%s\",\"median_ms\":%.4f}\n", w,
        h, properties.name, bilateralMs);
    cudaStreamDestroy(stream);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "denoise_gpu_bench: %s\n", e.what());
    return 1;
  }
  return 0;
}
