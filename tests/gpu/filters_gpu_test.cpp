// The CUDA filters against the CPU ones they mirror, and the OptiX backend's AOVs and device-side filtering
// against the CPU backend's.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "app/camera_path.h"
#include "backends/film_filters.h"
#include "backends/optix/filters/cuda_filters.h"
#include "gpu_render.h"
#include "image/filters/atrous.h"
#include "image/filters/bilateral.h"
#include "image/filters/temporal.h"

namespace candela {
namespace {

// The largest difference relative to max(|expected|, 1e-2), over all channels.
double worstRelativeError(const Image& actual, const Image& expected) {
  double worst = 0.0;
  for (size_t i = 0; i < expected.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double e = expected.pixels[i][c], a = actual.pixels[i][c];
      worst = std::fmax(worst, std::fabs(a - e) / std::fmax(std::fabs(e), 1e-2));
    }
  return worst;
}

// Both sides run the same float operations in the same order (IEEE division and square root on both). The
// bilateral filter fuses no multiply-adds on either side and gives identical images; the CPU a-trous filter
// fuses them where the processor has FMA, and the order of its mean-luminance sum (in double) differs, so
// a-trous images differ by rounding. The bound leaves room for that while a 2% parameter change still exceeds
// it.
constexpr double kTolerance = 1e-4;

struct Frame {
  Image color;
  AovImages aovs;
};

Frame renderedFrame() {
  auto backend = test::makeBackend<CpuBackend>(makeCornellBox(), test::squareImage(96, 1));
  backend->setAovsEnabled(true);
  backend->render(4);
  return {backend->readImage(), backend->readAovs()};
}

TEST(CudaFilters, AtrousMatchesTheCpuFilter) {
  const Frame f = renderedFrame();
  for (int passes : {1, 3, 5}) {
    AtrousParams params;
    params.passes = passes;
    const Image gpu = optix::atrousDenoiseCuda(f.color, f.aovs, params);
    const double error = worstRelativeError(gpu, atrousDenoise(f.color, f.aovs, params));
    std::printf("a-trous, %d passes: worst relative difference %.3g\n", passes, error);
    EXPECT_LE(error, kTolerance) << passes << " passes";
    AtrousParams off = params;
    off.colorSigma *= 1.02f;
    EXPECT_GT(worstRelativeError(gpu, atrousDenoise(f.color, f.aovs, off)), kTolerance)
        << "the comparison cannot tell a 2% colour-sigma change apart";
  }
}

TEST(CudaFilters, BilateralMatchesTheCpuFilter) {
  const Frame f = renderedFrame();
  for (BilateralParams params :
       {BilateralParams{0, 1.0f, 0.1f}, BilateralParams{3, 2.0f, 0.2f}, BilateralParams{5, 3.0f, 5.0f}}) {
    const Image gpu = optix::bilateralFilterCuda(f.color, params);
    const double error = worstRelativeError(gpu, bilateralFilter(f.color, params));
    std::printf("bilateral, radius %d: worst relative difference %.3g\n", params.radius, error);
    EXPECT_LE(error, kTolerance) << "radius " << params.radius;
    if (params.radius == 0) continue;
    BilateralParams off = params;
    off.rangeSigma *= 1.02f;
    EXPECT_GT(worstRelativeError(gpu, bilateralFilter(f.color, off)), kTolerance);
  }
}

// The first non-specular hit depends only on the camera ray, which both backends draw from the same random
// sequence: the AOVs agree closely, apart from pixels whose ray grazes an edge (GPU fast math).
TEST(OptixAovs, AgreeWithTheCpuBackend) {
  RenderSettings settings = test::squareImage(64, 2);
  auto cpu = test::makeBackend<CpuBackend>(makeCornellBox(), settings);
  auto gpu = test::makeBackend<OptixBackend>(makeCornellBox(), settings);
  cpu->setAovsEnabled(true);
  gpu->setAovsEnabled(true);
  cpu->render(4);
  gpu->render(4);
  const AovImages a = cpu->readAovs(), b = gpu->readAovs();
  size_t close = 0;
  for (size_t i = 0; i < a.depth.size(); ++i)
    if (length(a.albedo.pixels[i] - b.albedo.pixels[i]) < 1e-3f &&
        length(a.normal.pixels[i] - b.normal.pixels[i]) < 1e-3f &&
        std::fabs(a.depth[i] - b.depth[i]) < 1e-3f * a.depth[i] + 1e-5f)
      ++close;
  EXPECT_GE(double(close), 0.99 * double(a.depth.size()));
}

// The backend filters its film in device memory; the result must be the CPU filter's on the same film.
TEST(OptixFiltering, FiltersTheFilmOnTheDevice) {
  auto gpu = test::makeBackend<OptixBackend>(makeCornellBox(), test::squareImage(80, 3));
  gpu->setAovsEnabled(true);
  gpu->render(3);
  gpu->render(2);
  const Image image = gpu->readImage();
  const AovImages aovs = gpu->readAovs();
  EXPECT_LE(worstRelativeError(gpu->filters().atrous(AtrousParams{}), atrousDenoise(image, aovs, AtrousParams{})),
            kTolerance);
  EXPECT_LE(worstRelativeError(gpu->filters().bilateral(BilateralParams{}),
                               bilateralFilter(image, gpu->readEmission(), BilateralParams{})),
            kTolerance);
}

// The backend's temporal filter runs on the device with its history there; along a camera move, and for a film
// that goes on with more samples, it must give the CPU filter's images on the same films. Both sides make the same
// decisions in the same float operations (reprojection, rejection, accumulation, moments: no fused multiply-adds on
// either side, IEEE division and square root on both); only the a-trous passes differ by rounding, as above. The
// history carries those differences on through convex mixes (bilinear reprojection, accumulation), which do not
// grow them, so the a-trous bound holds; a 2% change of the colour sigma still exceeds it.
TEST(OptixFiltering, TemporalFilterMatchesTheCpuFilterAlongACameraMove) {
  const Scene scene = makeCornellBox();
  RenderSettings settings = test::squareImage(80, 5);
  auto gpu = test::makeBackend<OptixBackend>(scene, settings);
  gpu->setAovsEnabled(true);
  const TemporalParams params;
  TemporalParams off = params;
  off.atrous.colorSigma *= 1.02f;
  const std::unique_ptr<TemporalDenoiser> device = gpu->filters().temporal(params);
  TemporalFilter cpu(params), cpuOff(off);
  const std::vector<CameraDescription> path = orbitCameraPath(scene.camera, 6, 3.0f);
  auto compare = [&](const Camera& camera, bool filmContinues, const char* what) {
    const Image image = gpu->readImage();
    const AovImages aovs = gpu->readAovs();
    const TemporalFrame frame{image, aovs, camera, gpu->accumulatedSamples(), filmContinues};
    const Image filtered = device->denoise(camera, filmContinues);
    const double error = worstRelativeError(filtered, cpu.filter(frame));
    std::printf("temporal, %s: worst relative difference %.3g\n", what, error);
    EXPECT_LE(error, kTolerance) << what;
    EXPECT_GT(worstRelativeError(filtered, cpuOff.filter(frame)), kTolerance)
        << what << ": the comparison cannot tell a 2% colour-sigma change apart";
  };
  for (size_t f = 0; f < path.size(); ++f) {
    const Camera camera = path[f].toCamera(1.0f);
    settings.seed = uint32_t(f + 1);
    gpu->setSettings(settings);
    gpu->setCamera(camera);
    gpu->render(2);
    compare(camera, false, ("frame " + std::to_string(f)).c_str());
  }
  // The last film goes on: more samples, the same camera.
  gpu->render(2);
  compare(path.back().toCamera(1.0f), true, "the last frame's film continued");
}

// A closed sphere of albedo 0 emitting 2e38 inside: every sample is finite, any two sum to infinity. The OptiX
// film keeps one sample per pixel and drops and counts the other three, as the CPU film does; the image stays
// finite, and so does the a-trous filter's output on the device.
TEST(OptixFilm, DropsAndCountsSamplesThatWouldOverflow) {
  auto gpu = test::makeBackend<OptixBackend>(makeClosedEmissiveSphere(0.0f, 2e38f), test::squareImage(8, 1));
  gpu->setAovsEnabled(true);
  EXPECT_EQ(gpu->render(4).invalidSamples, 3u * 64u);
  for (const Vec3& p : gpu->readImage().pixels) EXPECT_FLOAT_EQ(p.x, 2e38f);
  // The filter clamps values above 1e18 (kMaxFilteredValue) but keeps them finite.
  for (const Vec3& p : gpu->filters().atrous(AtrousParams{}).pixels) EXPECT_TRUE(isFinite(p));
}

}  // namespace
}  // namespace candela
