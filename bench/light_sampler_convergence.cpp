// light_sampler_convergence: error against samples and time for the light samplers (the light BVH and the power
// table), on a generated town at night with thousands of small lights, a field of point lights
// (many_lights_scene.h) or any scene.
//   light_sampler_convergence [--scene night-town|point-field] [--blocks 24] [--point-lights 1000]
//                             [--backend cpu|optix] [--width 192]
//                             [--height 108] [--reference-spp 8192] [--max-spp 256] [--seeds 4]
//                             [--reference-image ref.exr]
// Renders a reference with the light BVH and the independent sampler at --reference-spp (its own seed), then
// for each light sampler and each power of two up to --max-spp the mean relMSE over --seeds renders (Sobol
// sampler) against it and the fastest time of one render at that count. Prints one JSON object per line: the
// curves, the equal-sample ratios (power table's relMSE over the BVH's) and the equal-time ratio at the time of
// the power table's 16 spp (log-log interpolation of the BVH's curve). Results: docs/performance.md.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <map>
#include <vector>

#include "app/scene_loading.h"
#include "convergence.h"
#include "io/images/image_io.h"
#include "many_lights_scene.h"

namespace candela {
namespace {

using bench::Point;

struct Options : bench::ConvergenceOptions {
  std::string scene = "night-town";
  uint32_t blocks = 24;
  uint32_t pointLights = 1000;
  std::string referenceImage;

  Options() {
    width = 192;
    height = 108;
    referenceSpp = 8192;
    maxSpp = 256;
  }
};

const char* lightSamplerName(LightSamplerKind kind) { return kind == LightSamplerKind::Bvh ? "bvh" : "power"; }

int run(const Options& options) {
  Scene scene = options.scene == "night-town"    ? makeNightTown(options.blocks, 1)
                : options.scene == "point-field" ? makePointLitField(options.pointLights, 1)
                                                 : loadScene(options.scene, {});
  bench::Renderer renderer = bench::Renderer::of(scene, options);
  double referenceMs = 0.0;
  renderer.settings.lightSampler = LightSamplerKind::Bvh;
  Image reference = renderer.renderReference(options.referenceSpp, referenceMs);
  if (!options.referenceImage.empty()) writeImage(options.referenceImage, reference, DisplaySettings{});
  std::printf(
      "{\"scene\": \"%s\", \"triangles\": %zu, \"punctual_lights\": %zu, \"reference_spp\": %u, \"reference_seconds\": "
      "%.1f, "
      "\"backend\": \"%s\", \"device\": \"%s\"}\n",
      scene.name.c_str(), scene.triangleCount(), scene.punctualLights.size(), options.referenceSpp,
      referenceMs / 1000.0, renderer.backend->name().c_str(), renderer.backend->deviceName().c_str());
  std::fflush(stdout);

  // The two light samplers take turns, render by render, so that both see the same load on a shared machine;
  // each point's time is the fastest of its seeds' renders, the least disturbed.
  std::map<LightSamplerKind, std::vector<Point>> curves;
  const LightSamplerKind kinds[] = {LightSamplerKind::Power, LightSamplerKind::Bvh};
  renderer.settings.sampler = SamplerKind::Sobol;
  for (uint32_t spp = 1; spp <= options.maxSpp; spp *= 2) {
    std::map<LightSamplerKind, double> fastest, errorSum;
    for (uint32_t seed = 0; seed < options.seeds; ++seed)
      for (LightSamplerKind kind : kinds) {
        double ms = 0.0;
        renderer.settings.lightSampler = kind;
        renderer.settings.seed = seed + 1;
        errorSum[kind] += bench::relMse(renderer.render(spp, ms), reference);
        fastest[kind] = seed == 0 ? ms : std::min(fastest[kind], ms);
      }
    for (LightSamplerKind kind : kinds) {
      Point p{spp, fastest[kind], errorSum[kind] / options.seeds};
      curves[kind].push_back(p);
      std::printf("{\"light_sampler\": \"%s\", \"spp\": %u, \"milliseconds\": %.3f, \"relmse\": %.6g}\n",
                  lightSamplerName(kind), spp, p.milliseconds, p.relMse);
    }
    std::fflush(stdout);
  }
  const std::vector<Point>&power = curves[LightSamplerKind::Power], &bvh = curves[LightSamplerKind::Bvh];
  for (size_t i = 0; i < power.size(); ++i)
    std::printf("{\"equal_spp\": %u, \"power_over_bvh\": %.3f}\n", power[i].spp, power[i].relMse / bvh[i].relMse);
  if (power.size() > 4) {
    const Point& at16 = power[4];
    double bvhAtTime = bench::relMseAtTime(bvh, at16.milliseconds);
    std::printf("{\"equal_time_ms\": %.3f, \"power_relmse\": %.6g, \"bvh_relmse\": %.6g, \"power_over_bvh\": %.3f}\n",
                at16.milliseconds, at16.relMse, bvhAtTime, at16.relMse / bvhAtTime);
  }
  return 0;
}

}  // namespace
}  // namespace candela

int main(int argc, char** argv) {
  candela::Options options;
  CLI::App app{"Error against samples and time for the light samplers"};
  app.add_option("--scene", options.scene, "night-town or point-field (generated), or a scene file or built-in scene")
      ->capture_default_str();
  app.add_option("--blocks", options.blocks, "night-town: blocks per side")
      ->check(CLI::Range(1u, 200u))
      ->capture_default_str();
  app.add_option("--point-lights", options.pointLights, "point-field: point lights")
      ->check(CLI::Range(1u, 1000000u))
      ->capture_default_str();
  candela::bench::addConvergenceOptions(app, options);
  app.add_option("--reference-image", options.referenceImage, "Write the reference here (.exr, .png, ...)");
  return candela::bench::runBenchmark(app, argc, argv, "light_sampler_convergence",
                                      [&] { return candela::run(options); });
}
