#pragma once
// What the convergence benchmarks share: their common options, relMSE against a reference (temporal_orbit's measure
// too), timed progressive renders, and reading a relMSE-against-time curve at a given time.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "app/backend_factory.h"
#include "backends/backend.h"
#include "image/image.h"
#include "kernel/render_settings.h"
#include "scene/scene.h"

namespace candela::bench {

// The options every convergence benchmark takes; each sets its own defaults.
struct ConvergenceOptions {
  std::string backend = "cpu";
  uint32_t width = 256, height = 256;
  uint32_t referenceSpp = 65536, maxSpp = 1024, seeds = 4;
};

inline void addConvergenceOptions(CLI::App& app, ConvergenceOptions& options) {
  app.add_option("--backend", options.backend, "cpu or optix")->capture_default_str();
  app.add_option("--width", options.width)->check(CLI::Range(1u, 8192u))->capture_default_str();
  app.add_option("--height", options.height)->check(CLI::Range(1u, 8192u))->capture_default_str();
  app.add_option("--reference-spp", options.referenceSpp)->check(CLI::Range(1u, 1u << 24))->capture_default_str();
  app.add_option("--max-spp", options.maxSpp)->check(CLI::Range(1u, 1u << 16))->capture_default_str();
  app.add_option("--seeds", options.seeds)->check(CLI::Range(1u, 64u))->capture_default_str();
}

// Parses the command line and runs the benchmark; a failure is one line naming `program`, and exit status 1.
inline int runBenchmark(CLI::App& app, int argc, char** argv, const char* program, const std::function<int()>& run) {
  CLI11_PARSE(app, argc, argv);
  try {
    return run();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", program, e.what());
    return 1;
  }
}

struct Point {
  uint32_t spp = 0;
  double milliseconds = 0.0;  // median over the seeds
  double relMse = 0.0;        // mean over the seeds
};

// relMSE as pbrt-v4's imgtool and the denoising literature use it: squared error over (reference^2 + 0.01).
inline double relMse(const Image& image, const Image& reference) {
  double sum = 0.0;
  for (size_t i = 0; i < image.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      double r = (&reference.pixels[i].x)[c], d = (&image.pixels[i].x)[c] - r;
      sum += d * d / (r * r + 0.01);
    }
  return sum / (3.0 * double(image.pixels.size()));
}

inline double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// The curve's relMSE at `milliseconds`, interpolated linearly in log-log between the points around it.
inline double relMseAtTime(const std::vector<Point>& curve, double milliseconds) {
  for (size_t i = 1; i < curve.size(); ++i)
    if (curve[i].milliseconds >= milliseconds) {
      const Point &a = curve[i - 1], &b = curve[i];
      double t =
          (std::log(milliseconds) - std::log(a.milliseconds)) / (std::log(b.milliseconds) - std::log(a.milliseconds));
      return std::exp(std::log(a.relMse) + t * (std::log(b.relMse) - std::log(a.relMse)));
    }
  return curve.back().relMse;
}

struct Renderer {
  std::unique_ptr<Backend> backend;
  RenderSettings settings;

  // A renderer of `scene` from its camera on the options' backend (which it names on stderr) at their size.
  static Renderer of(const Scene& scene, const ConvergenceOptions& options) {
    std::string why;
    Renderer renderer{createBackend(options.backend, why), {}};
    std::fprintf(stderr, "%s\n", why.c_str());
    renderer.settings.width = options.width;
    renderer.settings.height = options.height;
    renderer.backend->setScene(scene);
    renderer.backend->setCamera(scene.camera.toCamera(float(options.width) / float(options.height)));
    return renderer;
  }

  // Renders `spp` samples per pixel one launch at a time, as the viewer and `candela render` add them, and
  // times them; the first launch after a change of settings is not timed.
  Image render(uint32_t spp, double& milliseconds) {
    backend->setSettings(settings);
    backend->render(1);
    backend->setSettings(settings);  // restarts the film
    auto start = std::chrono::steady_clock::now();
    for (uint32_t s = 0; s < spp; ++s) backend->render(1);
    milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return backend->readImage();
  }

  // A reference of `spp` samples per pixel with the independent sampler at a seed of its own, rendered in
  // batches; returns its time in milliseconds.
  Image renderReference(uint32_t spp, double& milliseconds) {
    settings.sampler = SamplerKind::Independent;
    settings.seed = 1000003;
    backend->setSettings(settings);
    auto start = std::chrono::steady_clock::now();
    for (uint32_t done = 0; done < spp;) {
      uint32_t batch = std::min(64u, spp - done);
      backend->render(batch);
      done += batch;
    }
    milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return backend->readImage();
  }
};

}  // namespace candela::bench
