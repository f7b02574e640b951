// sampler_convergence: error against time for the path samplers, on one scene, backend and device.
//   sampler_convergence [--scene cornell-box] [--backend cpu|optix] [--width 256] [--height 256]
//                       [--reference-spp 65536] [--max-spp 1024] [--seeds 4] [--env map.hdr]
// Renders a reference with the independent sampler at --reference-spp (its own seed), then for each sampler and
// each power of two up to --max-spp the mean relMSE over --seeds renders against it and the median time of one
// render at that count (one launch per sample, as the viewer and `candela render` add them). Prints one JSON
// object per line, then the equal-time comparison: the independent sampler's relMSE at 16 spp over the Sobol
// sampler's relMSE at the same time (log-log interpolation of its curve). Results: docs/performance.md.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <vector>

#include "app/backend_factory.h"
#include "app/scene_loading.h"

namespace candela {
namespace {

struct Options {
  std::string scene = "cornell-box";
  std::string backend = "cpu";
  std::string environment;
  uint32_t width = 256, height = 256;
  uint32_t referenceSpp = 65536, maxSpp = 1024, seeds = 4;
};

struct Point {
  uint32_t spp = 0;
  double milliseconds = 0.0;  // median over the seeds
  double relMse = 0.0;        // mean over the seeds
};

// relMSE as pbrt-v4's imgtool and the denoising literature use it: squared error over (reference^2 + 0.01).
double relMse(const Image& image, const Image& reference) {
  double sum = 0.0;
  for (size_t i = 0; i < image.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      double r = (&reference.pixels[i].x)[c], d = (&image.pixels[i].x)[c] - r;
      sum += d * d / (r * r + 0.01);
    }
  return sum / (3.0 * double(image.pixels.size()));
}

struct Renderer {
  std::unique_ptr<Backend> backend;
  RenderSettings settings;

  Image render(SamplerKind kind, uint32_t seed, uint32_t spp, double& milliseconds) {
    settings.sampler = kind;
    settings.seed = seed;
    backend->setSettings(settings);
    backend->render(1);              // the first launch after a change is not timed
    backend->setSettings(settings);  // restarts the film
    auto start = std::chrono::steady_clock::now();
    for (uint32_t s = 0; s < spp; ++s) backend->render(1);
    milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return backend->readImage();
  }
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// The curve's relMSE at `milliseconds`, interpolated linearly in log-log between the points around it.
double relMseAtTime(const std::vector<Point>& curve, double milliseconds) {
  for (size_t i = 1; i < curve.size(); ++i)
    if (curve[i].milliseconds >= milliseconds) {
      const Point &a = curve[i - 1], &b = curve[i];
      double t =
          (std::log(milliseconds) - std::log(a.milliseconds)) / (std::log(b.milliseconds) - std::log(a.milliseconds));
      return std::exp(std::log(a.relMse) + t * (std::log(b.relMse) - std::log(a.relMse)));
    }
  return curve.back().relMse;
}

int run(const Options& options) {
  Scene scene = loadScene(options.scene, {options.environment, {}});
  std::string why;
  Renderer renderer{createBackend(options.backend, why), {}};
  std::fprintf(stderr, "%s\n", why.c_str());
  renderer.settings.width = options.width;
  renderer.settings.height = options.height;
  renderer.backend->setScene(scene);
  renderer.backend->setCamera(scene.camera.toCamera(float(options.width) / float(options.height)));

  double referenceMs = 0.0;
  renderer.settings.sampler = SamplerKind::Independent;
  renderer.settings.seed = 1000003;
  renderer.backend->setSettings(renderer.settings);
  auto start = std::chrono::steady_clock::now();
  for (uint32_t done = 0; done < options.referenceSpp;) {
    uint32_t batch = std::min(64u, options.referenceSpp - done);
    renderer.backend->render(batch);
    done += batch;
  }
  referenceMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  Image reference = renderer.backend->readImage();
  std::printf("{\"reference_spp\": %u, \"reference_seconds\": %.1f, \"backend\": \"%s\", \"device\": \"%s\"}\n",
              options.referenceSpp, referenceMs / 1000.0, renderer.backend->name().c_str(),
              renderer.backend->deviceName().c_str());

  std::map<SamplerKind, std::vector<Point>> curves;
  for (SamplerKind kind : {SamplerKind::Independent, SamplerKind::Sobol}) {
    const char* name = kind == SamplerKind::Sobol ? "sobol" : "independent";
    for (uint32_t spp = 1; spp <= options.maxSpp; spp *= 2) {
      std::vector<double> times;
      double errorSum = 0.0;
      for (uint32_t seed = 0; seed < options.seeds; ++seed) {
        double ms = 0.0;
        errorSum += relMse(renderer.render(kind, seed + 1, spp, ms), reference);
        times.push_back(ms);
      }
      Point p{spp, median(times), errorSum / options.seeds};
      curves[kind].push_back(p);
      std::printf("{\"sampler\": \"%s\", \"spp\": %u, \"milliseconds\": %.3f, \"relmse\": %.6g}\n", name, spp,
                  p.milliseconds, p.relMse);
      std::fflush(stdout);
    }
  }
  const std::vector<Point>& independent = curves[SamplerKind::Independent];
  if (options.maxSpp >= 32) {
    const Point& at16 = independent[4];
    double sobol = relMseAtTime(curves[SamplerKind::Sobol], at16.milliseconds);
    std::printf(
        "{\"equal_time_ms\": %.3f, \"independent_relmse\": %.6g, \"sobol_relmse\": %.6g, "
        "\"independent_over_sobol\": %.3f}\n",
        at16.milliseconds, at16.relMse, sobol, at16.relMse / sobol);
  }
  return 0;
}

}  // namespace
}  // namespace candela

int main(int argc, char** argv) {
  candela::Options options;
  CLI::App app{"Error against time for the path samplers"};
  app.add_option("--scene", options.scene, "Scene file or built-in scene")->capture_default_str();
  app.add_option("--backend", options.backend, "cpu or optix")->capture_default_str();
  app.add_option("--env", options.environment, "Environment map");
  app.add_option("--width", options.width)->capture_default_str();
  app.add_option("--height", options.height)->capture_default_str();
  app.add_option("--reference-spp", options.referenceSpp)->capture_default_str();
  app.add_option("--max-spp", options.maxSpp)->capture_default_str();
  app.add_option("--seeds", options.seeds)->check(CLI::Range(1u, 64u))->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  try {
    return candela::run(options);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sampler_convergence: %s\n", e.what());
    return 1;
  }
}
