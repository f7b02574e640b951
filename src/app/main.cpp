#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "app/backend_factory.h"
#include "app/render_job.h"
#include "app/scene_loading.h"
#include "image/image_io.h"
#include "scene/builtin_scenes.h"

using namespace candela;

namespace {

void addRenderOptions(CLI::App& cmd, RenderJob& job) {
  std::string scenes;
  for (const std::string& n : builtinSceneNames()) scenes += (scenes.empty() ? "" : ", ") + n;
  cmd.add_option("scene", job.sceneSpec, "Scene file (.obj, .gltf, .glb, .json) or built-in scene (" + scenes + ")")
      ->capture_default_str();
  cmd.add_option("--env", job.environmentPath, "Environment map (.hdr or .exr) that lights the scene");
  cmd.add_option("--spp", job.samplesPerPixel, "Samples per pixel")
      ->check(CLI::Range(1u, 1u << 24))
      ->capture_default_str();
  cmd.add_option("--width", job.settings.width, "Image width in pixels")
      ->check(CLI::Range(1u, 16384u))
      ->capture_default_str();
  cmd.add_option("--height", job.settings.height, "Image height in pixels")
      ->check(CLI::Range(1u, 16384u))
      ->capture_default_str();
  cmd.add_option("--max-depth", job.settings.maxDepth,
                 "Longest path in bounces after the camera ray (1 = direct light only)")
      ->check(CLI::Range(1u, 1024u))
      ->capture_default_str();
  cmd.add_option("--seed", job.settings.seed, "Seed of the random sequence; same seed, same image")
      ->capture_default_str();
  // Validated while parsing, so a bad value is a usage error (exit status 2) like any other.
  auto validated = [](auto apply) {
    return CLI::Validator(
        [apply](std::string& text) {
          try {
            apply(text);
          } catch (const std::invalid_argument& e) {
            return std::string(e.what());
          }
          return std::string();
        },
        "", "");
  };
  cmd.add_option_function<std::string>("--shading", [&job](const std::string& name) {
        job.materialOverrides.shading = parseShadingModel(name);
      }, "Render every material with one shading model: phong, pbr or disney (default: each material's own)")
      ->check(validated([](const std::string& name) { parseShadingModel(name); }));
  std::string overrideNames;
  for (const OverrideParameter& p : overrideParameters()) overrideNames += (overrideNames.empty() ? "" : ", ") + std::string(p.name);
  cmd.add_option_function<std::vector<std::string>>("--override", [&job](const std::vector<std::string>& list) {
        for (const std::string& assignment : list) parseOverride(job.materialOverrides, assignment);
      }, "Set a material parameter on every material, name=value in [0, 1]; repeatable. Names: " + overrideNames)
      ->check(validated([](const std::string& assignment) {
        MaterialOverrides scratch;
        parseOverride(scratch, assignment);
      }));
  cmd.add_option("--backend", job.backend, "auto, cpu or optix (in this build: " + availableBackends() + ")")
      ->check(CLI::IsMember({"auto", "cpu", "optix"}))
      ->capture_default_str();
}

std::string formatRate(double perSecond) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.2f", perSecond / 1e6);
  return buffer;
}

// Fails early, before a long render, when the output cannot be written.
void checkOutputPath(const std::string& path) {
  if (!isSupportedImageExtension(path))
    throw std::runtime_error("cannot write '" + path + "': use a .png, .exr or .pfm file name");
  std::filesystem::path dir = std::filesystem::path(path).parent_path();
  if (dir.empty()) dir = ".";
  if (!std::filesystem::is_directory(dir))
    throw std::runtime_error("cannot write '" + path + "': directory '" + dir.string() + "' does not exist");
  if (access(dir.c_str(), W_OK) != 0)
    throw std::runtime_error("cannot write '" + path + "': directory '" + dir.string() + "' is not writable");
}

int runRender(const RenderJob& job, const std::string& output, const DisplaySettings& display) {
  checkOutputPath(output);
  RenderOutcome outcome = runRenderJob(job, /*showProgress=*/true);
  writeImage(output, outcome.image, display);
  double samples = double(job.settings.width) * job.settings.height * job.samplesPerPixel;
  std::fprintf(stderr, "rendered %ux%u at %u spp in %.2f s: %s Msamples/s, %s Mrays/s, %llu invalid samples dropped\n",
               job.settings.width, job.settings.height, job.samplesPerPixel, outcome.seconds,
               formatRate(samples / outcome.seconds).c_str(), formatRate(double(outcome.stats.rays) / outcome.seconds).c_str(),
               (unsigned long long)outcome.stats.invalidSamples);
  std::printf("%s\n", std::filesystem::absolute(output).string().c_str());
  return 0;
}

int runBench(const RenderJob& job) {
  RenderOutcome outcome = runRenderJob(job, /*showProgress=*/false);
  double samples = double(job.settings.width) * job.settings.height * job.samplesPerPixel;
  nlohmann::ordered_json report = {
      {"scene", outcome.sceneName},
      {"width", job.settings.width},
      {"height", job.settings.height},
      {"spp", job.samplesPerPixel},
      {"max_depth", job.settings.maxDepth},
      {"backend", outcome.backendName},
      {"device", outcome.deviceName},
      {"seconds", outcome.seconds},
      {"msamples_per_s", samples / outcome.seconds / 1e6},
      {"mrays_per_s", double(outcome.stats.rays) / outcome.seconds / 1e6},
      {"invalid_samples", outcome.stats.invalidSamples},
  };
  std::cout << report.dump() << std::endl;
  return 0;
}

int runLoad(const std::string& spec) {
  auto start = std::chrono::steady_clock::now();
  Scene scene = loadScene(spec);
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  size_t vertices = 0;
  for (const Mesh& m : scene.meshes) vertices += m.positions.size();
  nlohmann::ordered_json report = {
      {"scene", spec},
      {"seconds", seconds},
      {"meshes", scene.meshes.size()},
      {"instances", scene.instances.size()},
      {"triangles", scene.triangleCount()},
      {"vertices", vertices},
      {"materials", scene.materials.size()},
      {"textures", scene.textures.size()},
      {"scene_bytes", sceneMemoryBytes(scene)},
  };
  std::cout << report.dump() << std::endl;
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"candela: a physically based path tracer.\n"
               "  candela render                 render the built-in Cornell box to candela.png\n"
               "  candela render -o box.exr --spp 256\n"
               "  candela bench --spp 16         print one JSON line of timings"};
  app.require_subcommand(1);

  RenderJob renderJob;
  std::string output = "candela.png";
  DisplaySettings display;
  std::string toneMapper = "aces";
  CLI::App* render = app.add_subcommand("render", "Render a scene to an image file");
  addRenderOptions(*render, renderJob);
  render->add_option("-o,--output", output, "Output image: .png (tone mapped), .exr or .pfm (linear)")
      ->capture_default_str();
  render->add_option("--exposure", display.exposure, "Exposure in stops, for .png")->capture_default_str();
  render->add_option("--tonemap", toneMapper, "Tone mapper for .png: aces or clamp")
      ->check(CLI::IsMember({"aces", "clamp"}))
      ->capture_default_str();

  RenderJob benchJob;
  benchJob.samplesPerPixel = 16;
  CLI::App* bench = app.add_subcommand("bench", "Time a render and print the numbers as one JSON object");
  addRenderOptions(*bench, benchJob);

  std::string inspectSpec;
  CLI::App* inspect = app.add_subcommand("load", "Load a scene and print its size and loading time as one JSON object");
  inspect->add_option("scene", inspectSpec, "Scene file or built-in scene")->required();

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "candela: %s (see candela --help)\n", e.what());
    return 2;
  }

  for (auto [cmd, job] : {std::pair{render, &renderJob}, std::pair{bench, &benchJob}}) {
    job->given.width = cmd->count("--width") > 0;
    job->given.height = cmd->count("--height") > 0;
    job->given.samplesPerPixel = cmd->count("--spp") > 0;
    job->given.maxDepth = cmd->count("--max-depth") > 0;
  }

  try {
    if (*inspect) return runLoad(inspectSpec);
    if (*render) {
      display.toneMapper = toneMapper == "clamp" ? ToneMapper::Clamp : ToneMapper::AcesFilmic;
      return runRender(renderJob, output, display);
    }
    return runBench(benchJob);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "candela: %s\n", e.what());
    return 1;
  }
}
