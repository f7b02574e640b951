// temporal_orbit: the temporal filter against the spatial a-trous filter along an orbit, on the CPU backend.
//   temporal_orbit [--scene cornell-box] [--size 96] [--frames 120] [--degrees 30] [--reference-spp 512]
//                  [--strip DIR]
// Renders each frame of the orbit (app/camera_path.h) at 1 sample per pixel with AOVs on a fresh film, filters it
// spatially (atrousDenoise) and temporally (TemporalFilter, history from the frames before), and renders a
// reference of the same view at --reference-spp. Prints per-frame relMSE (raw, spatial, temporal) every tenth
// frame, their means over the last quarter, and the temporal stability: the mean absolute frame-to-frame change of
// the filtered luminance over the static pixels (those whose reference luminance changed by less than 1% + 0.001
// from the previous frame), next to the reference's own change there. With --strip, writes raw, spatial, temporal
// and reference PNGs of the first, middle and last frames to DIR. Results: docs/denoising.md.
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "app/camera_path.h"
#include "app/scene_loading.h"
#include "backends/cpu/cpu_backend.h"
#include "convergence.h"
#include "image/filters/temporal.h"
#include "io/images/image_io.h"

namespace candela {
namespace {

struct Stability {
  double sum = 0.0, referenceSum = 0.0;
  size_t pixels = 0;
  // Adds the changes from `before` to `after` over the pixels whose reference is static.
  void add(const Image& before, const Image& after, const Image& referenceBefore, const Image& referenceAfter) {
    for (size_t i = 0; i < after.pixels.size(); ++i) {
      const double r0 = luminance(referenceBefore.pixels[i]), r1 = luminance(referenceAfter.pixels[i]);
      if (std::fabs(r1 - r0) > 0.01 * std::fabs(r0) + 1e-3) continue;
      sum += std::fabs(luminance(after.pixels[i]) - luminance(before.pixels[i]));
      referenceSum += std::fabs(r1 - r0);
      ++pixels;
    }
  }
  double mean() const { return pixels ? sum / double(pixels) : 0.0; }
};

}  // namespace
}  // namespace candela

int main(int argc, char** argv) {
  using namespace candela;
  std::string sceneSpec = "cornell-box", stripDir;
  uint32_t size = 96, frames = 120, referenceSpp = 512;
  float degrees = 30.0f;
  CLI::App app{"The temporal filter against the spatial one along an orbit"};
  app.add_option("--scene", sceneSpec);
  app.add_option("--size", size);
  app.add_option("--frames", frames);
  app.add_option("--degrees", degrees);
  app.add_option("--reference-spp", referenceSpp);
  app.add_option("--strip", stripDir);
  CLI11_PARSE(app, argc, argv);
  try {
    const Scene scene = loadScene(sceneSpec, {});
    const std::vector<CameraDescription> path = orbitCameraPath(scene.camera, frames, degrees);
    RenderSettings settings;
    settings.width = settings.height = size;
    CpuBackend noisy, converged;
    for (CpuBackend* b : {&noisy, &converged}) {
      b->setScene(scene);
      b->setSettings(settings);
    }
    noisy.setAovsEnabled(true);
    TemporalFilter temporal;
    Image previousSpatial, previousTemporal, previousReference;
    Stability spatialStability, temporalStability;
    double tailRaw = 0.0, tailSpatial = 0.0, tailTemporal = 0.0;
    size_t tail = 0;
    std::printf("| frame | raw | a-trous | temporal |\n| --- | --- | --- | --- |\n");
    for (uint32_t f = 0; f < frames; ++f) {
      const Camera camera = path[f].toCamera(1.0f);
      noisy.setCamera(camera);
      // A new seed every frame: the noise of successive frames is independent, as in the viewer.
      settings.seed = f + 1;
      noisy.setSettings(settings);
      noisy.render(1);
      converged.setCamera(camera);
      converged.render(referenceSpp);
      const Image raw = noisy.readImage(), reference = converged.readImage();
      const AovImages aovs = noisy.readAovs();
      const Image spatial = atrousDenoise(raw, aovs, AtrousParams{});
      const Image filtered = temporal.filter({raw, aovs, camera, 1, false});
      const double r = bench::relMse(raw, reference), s = bench::relMse(spatial, reference),
                   t = bench::relMse(filtered, reference);
      if (f % 10 == 0 || f + 1 == frames) std::printf("| %u | %.4f | %.4f | %.4f |\n", f, r, s, t);
      if (f >= frames - frames / 4) {
        tailRaw += r;
        tailSpatial += s;
        tailTemporal += t;
        ++tail;
      }
      if (f > 0) {
        spatialStability.add(previousSpatial, spatial, previousReference, reference);
        temporalStability.add(previousTemporal, filtered, previousReference, reference);
      }
      if (!stripDir.empty() && (f == 0 || f == frames / 2 || f + 1 == frames)) {
        DisplaySettings display;
        const std::string prefix = stripDir + "/orbit-" + std::to_string(f) + "-";
        writeImage(prefix + "raw.png", raw, display);
        writeImage(prefix + "atrous.png", spatial, display);
        writeImage(prefix + "temporal.png", filtered, display);
        writeImage(prefix + "reference.png", reference, display);
      }
      previousSpatial = spatial;
      previousTemporal = filtered;
      previousReference = reference;
    }
    std::printf("mean relMSE over the last %zu frames: raw %.4f, a-trous %.4f, temporal %.4f\n", tail,
                tailRaw / double(tail), tailSpatial / double(tail), tailTemporal / double(tail));
    std::printf(
        "mean |frame-to-frame change| of luminance over %zu static pixel-frames: a-trous %.5f, temporal %.5f, "
        "reference %.5f\n",
        temporalStability.pixels, spatialStability.mean(), temporalStability.mean(),
        temporalStability.pixels ? temporalStability.referenceSum / double(temporalStability.pixels) : 0.0);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "temporal_orbit: %s\n", e.what());
    return 1;
  }
  return 0;
}
