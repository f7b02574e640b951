#include "backends/cpu/cpu_backend.h"

#include <tbb/blocked_range2d.h>
#include <tbb/combinable.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>

#include <fstream>
#include <stdexcept>

#include "backends/cpu/embree_tracer.h"
#include "kernel/integrator.h"

namespace candela {

namespace {

std::string processorName() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line;
  while (std::getline(cpuinfo, line))
    if (line.rfind("model name", 0) == 0) {
      size_t colon = line.find(':');
      if (colon != std::string::npos) return line.substr(line.find_first_not_of(' ', colon + 1));
    }
  return "unknown CPU";
}

constexpr size_t kTileSize = 16;

}  // namespace

CpuBackend::CpuBackend() { restart(); }

std::string CpuBackend::deviceName() const {
  return processorName() + " (" + std::to_string(tbb::info::default_concurrency()) + " threads)";
}

void CpuBackend::setScene(const Scene& scene) {
  flat_ = FlatScene::build(scene);
  embree_.build(flat_);
  restart();
}

bool CpuBackend::setMaterials(const std::vector<Material>& materials) {
  if (!flat_.replaceMaterials(materials)) return false;
  if (!embree_.filtersMatch(flat_)) embree_.build(flat_);
  restart();
  return true;
}

void CpuBackend::setEnvironment(const Environment& environment) {
  flat_.replaceEnvironment(environment);
  restart();
}

void CpuBackend::setCamera(const Camera& camera) {
  camera_ = camera;
  restart();
}

void CpuBackend::setSettings(const RenderSettings& settings) {
  settings_ = settings;
  restart();
}

void CpuBackend::setAovsEnabled(bool enabled) {
  aovsEnabled_ = enabled;
  restart();
}

void CpuBackend::restart() {
  const size_t pixels = size_t(settings_.width) * settings_.height;
  sum_.assign(pixels, Vec3{});
  albedoSum_.assign(aovsEnabled_ ? pixels : 0, Vec3{});
  normalSum_.assign(aovsEnabled_ ? pixels : 0, Vec3{});
  depthSum_.assign(aovsEnabled_ ? pixels : 0, 0.0f);
  accumulated_ = 0;
}

FrameStats CpuBackend::render(uint32_t samplesPerPixel) {
  return aovsEnabled_ ? renderSamples<true>(samplesPerPixel) : renderSamples<false>(samplesPerPixel);
}

template <bool kWithAovs>
FrameStats CpuBackend::renderSamples(uint32_t samplesPerPixel) {
  const SceneView scene = flat_.hostView();
  const EmbreeTracer tracer(embree_.topLevel(), scene);
  const uint32_t firstSample = accumulated_;
  tbb::combinable<FrameStats> stats;
  tbb::parallel_for(
      tbb::blocked_range2d<uint32_t>(0, settings_.height, kTileSize, 0, settings_.width, kTileSize),
      [&](const tbb::blocked_range2d<uint32_t>& tile) {
        FrameStats& local = stats.local();
        for (uint32_t y = tile.rows().begin(); y < tile.rows().end(); ++y)
          for (uint32_t x = tile.cols().begin(); x < tile.cols().end(); ++x) {
            Vec3 pixelSum{};
            PathAovs aovSum;
            for (uint32_t s = 0; s < samplesPerPixel; ++s) {
              PathResult path =
                  renderPixelSample<kWithAovs>(scene, tracer, camera_, settings_, x, y, firstSample + s);
              local.rays += path.rays;
              if (isValidSample(path.radiance))
                pixelSum += path.radiance;
              else
                ++local.invalidSamples;
              if constexpr (kWithAovs) {
                aovSum.albedo += path.aovs.albedo;
                aovSum.normal += path.aovs.normal;
                aovSum.depth += path.aovs.depth;
              }
            }
            const size_t pixel = size_t(y) * settings_.width + x;
            sum_[pixel] += pixelSum;
            if constexpr (kWithAovs) {
              albedoSum_[pixel] += aovSum.albedo;
              normalSum_[pixel] += aovSum.normal;
              depthSum_[pixel] += aovSum.depth;
            }
          }
      });
  accumulated_ += samplesPerPixel;
  FrameStats total;
  stats.combine_each([&](const FrameStats& s) {
    total.rays += s.rays;
    total.invalidSamples += s.invalidSamples;
  });
  return total;
}

Image CpuBackend::readImage() const {
  Image image(settings_.width, settings_.height);
  float scale = accumulated_ > 0 ? 1.0f / float(accumulated_) : 0.0f;
  for (size_t i = 0; i < sum_.size(); ++i) image.pixels[i] = sum_[i] * scale;
  return image;
}

AovImages CpuBackend::readAovs() const {
  if (!aovsEnabled_) throw std::logic_error("CpuBackend::readAovs without setAovsEnabled(true)");
  AovImages aovs(settings_.width, settings_.height);
  float scale = accumulated_ > 0 ? 1.0f / float(accumulated_) : 0.0f;
  for (size_t i = 0; i < sum_.size(); ++i) {
    aovs.albedo.pixels[i] = albedoSum_[i] * scale;
    aovs.normal.pixels[i] = normalSum_[i] * scale;
    aovs.depth[i] = depthSum_[i] * scale;
  }
  return aovs;
}

}  // namespace candela
