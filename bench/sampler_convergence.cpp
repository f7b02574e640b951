// sampler_convergence: error against time for the path samplers, on one scene, backend and device.
//   sampler_convergence [--scene cornell-box] [--backend cpu|optix] [--width 256] [--height 256]
//                       [--reference-spp 65536] [--max-spp 1024] [--seeds 4] [--env map.hdr]
// Renders a reference with the independent sampler at --reference-spp (its own seed), then for each sampler and
// each power of two up to --max-spp the mean relMSE over --seeds renders against it and the median time of one
// render at that count (one launch per sample, as the viewer and `candela render` add them). Prints one JSON
// object per line, then the equal-time comparison: the independent sampler's relMSE at 16 spp over the Sobol
// sampler's relMSE at the same time (log-log interpolation of its curve). Results: docs/performance.md.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <map>
#include <vector>

#include "app/scene_loading.h"
#include "convergence.h"

namespace candela {
namespace {

using bench::Point;

struct Options : bench::ConvergenceOptions {
  std::string scene = "cornell-box";
  std::string environment;
};

int run(const Options& options) {
  Scene scene = loadScene(options.scene, {options.environment, {}});
  bench::Renderer renderer = bench::Renderer::of(scene, options);
  double referenceMs = 0.0;
  Image reference = renderer.renderReference(options.referenceSpp, referenceMs);
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
        renderer.settings.sampler = kind;
        renderer.settings.seed = seed + 1;
        errorSum += bench::relMse(renderer.render(spp, ms), reference);
        times.push_back(ms);
      }
      Point p{spp, bench::median(times), errorSum / options.seeds};
      curves[kind].push_back(p);
      std::printf("{\"sampler\": \"%s\", \"spp\": %u, \"milliseconds\": %.3f, \"relmse\": %.6g}\n", name, spp,
                  p.milliseconds, p.relMse);
      std::fflush(stdout);
    }
  }
  const std::vector<Point>& independent = curves[SamplerKind::Independent];
  if (options.maxSpp >= 32) {
    const Point& at16 = independent[4];
    double sobol = bench::relMseAtTime(curves[SamplerKind::Sobol], at16.milliseconds);
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
  app.add_option("--env", options.environment, "Environment map");
  candela::bench::addConvergenceOptions(app, options);
  return candela::bench::runBenchmark(app, argc, argv, "sampler_convergence", [&] { return candela::run(options); });
}
