// restir_convergence: error against samples and time with and without ReSTIR DI (--restir), on the generated town at
// night with thousands of small lights (many_lights_scene.h), on the tests' floor under many small lights
// (tests/support/many_small_lights.h: --scene many-small-lights, --lights of them, two triangles each) or any scene.
//   restir_convergence [--blocks 12] [--backend cpu] [--width 160] [--height 90] [--reference-spp 2048]
//                      [--max-spp 64] [--seeds 2] [--max-depth 8] [--scene FILE] [--lights 300]
// Renders a reference without ReSTIR (independent sampler, a seed of its own) at --reference-spp, then for each mode
// (off, di, di-biased) and each power of two up to --max-spp the mean relMSE over --seeds renders (Sobol sampler)
// against it, and the fastest time of one render at that count. Prints one JSON object per line: the curves, the
// equal-sample ratios (off's relMSE over di's and over di-biased's), the equal-time ratios at the time of off's
// largest count, and each mode's image-mean difference from the reference at --max-spp (the biased mode's bias shows
// there, beside the noise the unbiased ones leave). Results: docs/performance.md, 'ReSTIR DI'.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <map>
#include <vector>

#include "app/scene_loading.h"
#include "convergence.h"
#include "many_lights_scene.h"
#include "support/many_small_lights.h"

namespace candela {
namespace {

using bench::Point;

struct Options : bench::ConvergenceOptions {
  std::string scene = "night-town";
  uint32_t blocks = 12;
  uint32_t lights = 300;
  uint32_t maxDepth = RenderSettings{}.maxDepth;  // 1: the direct light alone, all of which ReSTIR estimates

  Options() {
    width = 160;
    height = 90;
    referenceSpp = 2048;
    maxSpp = 64;
    seeds = 2;
  }
};

const char* modeName(RestirMode mode) {
  return mode == RestirMode::Off ? "off" : mode == RestirMode::Di ? "di" : "di-biased";
}

double imageMean(const Image& image) {
  double sum = 0.0;
  for (const Vec3& p : image.pixels) sum += double(p.x) + p.y + p.z;
  return sum / (3.0 * double(image.pixels.size()));
}

int run(const Options& options) {
  Scene scene = options.scene == "night-town"          ? makeNightTown(options.blocks, 1)
                : options.scene == "many-small-lights" ? test::makeManySmallLights(options.lights, 5)
                                                       : loadScene(options.scene, {});
  bench::Renderer renderer = bench::Renderer::of(scene, options);
  renderer.settings.maxDepth = options.maxDepth;
  double referenceMs = 0.0;
  renderer.settings.restir = RestirMode::Off;
  const Image reference = renderer.renderReference(options.referenceSpp, referenceMs);
  const double referenceMean = imageMean(reference);
  std::printf(
      "{\"scene\": \"%s\", \"triangles\": %zu, \"max_depth\": %u, \"reference_spp\": %u, \"reference_seconds\": "
      "%.1f, \"backend\": \"%s\", \"device\": \"%s\"}\n",
      scene.name.c_str(), scene.triangleCount(), options.maxDepth, options.referenceSpp, referenceMs / 1000.0,
      renderer.backend->name().c_str(), renderer.backend->deviceName().c_str());
  std::fflush(stdout);

  // The modes take turns, render by render, so that all see the same load on a shared machine; each point's time
  // is the fastest of its seeds' renders, the least disturbed.
  const RestirMode modes[] = {RestirMode::Off, RestirMode::Di, RestirMode::DiBiased};
  std::map<RestirMode, std::vector<Point>> curves;
  std::map<RestirMode, double> lastMean;
  renderer.settings.sampler = SamplerKind::Sobol;
  for (uint32_t spp = 1; spp <= options.maxSpp; spp *= 2) {
    std::map<RestirMode, double> fastest, errorSum, meanSum;
    for (uint32_t seed = 0; seed < options.seeds; ++seed)
      for (RestirMode mode : modes) {
        double ms = 0.0;
        renderer.settings.restir = mode;
        renderer.settings.seed = seed + 1;
        const Image image = renderer.render(spp, ms);
        errorSum[mode] += bench::relMse(image, reference);
        meanSum[mode] += imageMean(image);
        fastest[mode] = seed == 0 ? ms : std::min(fastest[mode], ms);
      }
    for (RestirMode mode : modes) {
      Point p{spp, fastest[mode], errorSum[mode] / options.seeds};
      curves[mode].push_back(p);
      lastMean[mode] = meanSum[mode] / options.seeds;
      std::printf("{\"restir\": \"%s\", \"spp\": %u, \"milliseconds\": %.3f, \"relmse\": %.6g}\n", modeName(mode), spp,
                  p.milliseconds, p.relMse);
    }
    std::fflush(stdout);
  }
  const std::vector<Point>& off = curves[RestirMode::Off];
  for (size_t i = 0; i < off.size(); ++i)
    std::printf("{\"equal_spp\": %u, \"off_over_di\": %.3f, \"off_over_di_biased\": %.3f}\n", off[i].spp,
                off[i].relMse / curves[RestirMode::Di][i].relMse,
                off[i].relMse / curves[RestirMode::DiBiased][i].relMse);
  const Point& last = off.back();
  for (RestirMode mode : {RestirMode::Di, RestirMode::DiBiased}) {
    const double atTime = bench::relMseAtTime(curves[mode], last.milliseconds);
    std::printf(
        "{\"equal_time_ms\": %.3f, \"restir\": \"%s\", \"off_relmse\": %.6g, \"relmse\": %.6g, "
        "\"off_over_restir\": %.3f}\n",
        last.milliseconds, modeName(mode), last.relMse, atTime, last.relMse / atTime);
  }
  for (RestirMode mode : modes)
    std::printf("{\"restir\": \"%s\", \"spp\": %u, \"image_mean_over_reference\": %.5f}\n", modeName(mode), last.spp,
                lastMean[mode] / referenceMean);
  return 0;
}

}  // namespace
}  // namespace candela

int main(int argc, char** argv) {
  candela::Options options;
  CLI::App app{"Error against samples and time with and without ReSTIR DI"};
  app.add_option("--scene", options.scene,
                 "night-town or many-small-lights (generated), or a scene file or built-in scene")
      ->capture_default_str();
  app.add_option("--blocks", options.blocks, "night-town: blocks per side")
      ->check(CLI::Range(1u, 200u))
      ->capture_default_str();
  app.add_option("--lights", options.lights, "many-small-lights: lights (two emissive triangles each)")
      ->check(CLI::Range(1u, 100000u))
      ->capture_default_str();
  app.add_option("--max-depth", options.maxDepth, "Bounces after the camera ray (1: direct light only)")
      ->check(CLI::Range(1u, 1024u))
      ->capture_default_str();
  candela::bench::addConvergenceOptions(app, options);
  return candela::bench::runBenchmark(app, argc, argv, "restir_convergence", [&] { return candela::run(options); });
}
