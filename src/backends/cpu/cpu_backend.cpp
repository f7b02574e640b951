#include "backends/cpu/cpu_backend.h"

#include <tbb/blocked_range2d.h>
#include <tbb/combinable.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>

#include <fstream>
#include <stdexcept>

#include "backends/cpu/embree_tracer.h"
#include "kernel/film_accumulation.h"
#include "kernel/restir/restir_passes.h"

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

void CpuBackend::setInstanceTransforms(const Scene& scene) {
  if (!flat_.replaceInstanceTransforms(scene)) return setScene(scene);
  embree_.updateInstanceTransforms(flat_);
  restart();
}

void CpuBackend::setDeformedMeshes(const Scene& scene, const std::vector<uint32_t>& deformed) {
  if (!flat_.replaceMeshVertices(scene, deformed) || !flat_.replaceInstanceTransforms(scene)) return setScene(scene);
  embree_.updateMeshVertices(flat_, deformed);
  embree_.updateInstanceTransforms(flat_);
  restart();
}

void CpuBackend::setCamera(const Camera& camera) {
  camera_ = camera;
  restart(/*keepRestirHistory=*/true);
}

void CpuBackend::setSettings(const RenderSettings& settings) {
  settings_ = settings;
  restart();
}

void CpuBackend::setAovsEnabled(bool enabled) {
  aovsEnabled_ = enabled;
  restart();
}

void CpuBackend::restart(bool keepRestirHistory) {
  film_.reset(settings_.width, settings_.height, aovsEnabled_);
  accumulated_ = 0;
  nextSample_ = 0;
  if (settings_.restir == RestirMode::Off) {
    restir_.reset(0, 0);
  } else if (!keepRestirHistory) {
    restir_.reset(settings_.width, settings_.height);
  }
}

FrameStats CpuBackend::render(uint32_t samplesPerPixel) {
  const bool media = !flat_.media.empty();
  if (settings_.restir != RestirMode::Off && media)
    throw std::invalid_argument("--restir does not render participating media: use --restir off");
  if (settings_.restir != RestirMode::Off)
    return aovsEnabled_ ? renderRestirSamples<true>(samplesPerPixel) : renderRestirSamples<false>(samplesPerPixel);
  if (media)
    return aovsEnabled_ ? renderSamples<true, true>(samplesPerPixel) : renderSamples<false, true>(samplesPerPixel);
  return aovsEnabled_ ? renderSamples<true, false>(samplesPerPixel) : renderSamples<false, false>(samplesPerPixel);
}

// The film holds `samplesPerPixel` more samples; the threads' counts of them, summed.
FrameStats CpuBackend::finishSamples(uint32_t samplesPerPixel, tbb::combinable<FrameStats>& stats) {
  accumulated_ += samplesPerPixel;
  nextSample_ += samplesPerPixel;
  FrameStats total;
  stats.combine_each([&](const FrameStats& s) {
    total.rays += s.rays;
    total.invalidSamples += s.invalidSamples;
  });
  return total;
}

template <bool kWithAovs, bool kWithMedia>
FrameStats CpuBackend::renderSamples(uint32_t samplesPerPixel) {
  const SceneView scene = flat_.hostView();
  const EmbreeTracer tracer(embree_.topLevel(), scene);
  const uint32_t firstSample = nextSample_;
  const FilmView film = film_.view();
  tbb::combinable<FrameStats> stats;
  tbb::parallel_for(tbb::blocked_range2d<uint32_t>(0, settings_.height, kTileSize, 0, settings_.width, kTileSize),
                    [&](const tbb::blocked_range2d<uint32_t>& tile) {
                      FrameStats& local = stats.local();
                      for (uint32_t y = tile.rows().begin(); y < tile.rows().end(); ++y)
                        for (uint32_t x = tile.cols().begin(); x < tile.cols().end(); ++x) {
                          const PixelTally tally = accumulatePixel<kWithAovs>(
                              film, size_t(y) * settings_.width + x, firstSample, samplesPerPixel, [&](uint32_t s) {
                                return renderPixelSample<kWithAovs, kWithMedia>(scene, tracer, camera_, settings_, x, y,
                                                                                s);
                              });
                          local.rays += tally.rays;
                          local.invalidSamples += tally.invalidSamples;
                        }
                    });
  return finishSamples(samplesPerPixel, stats);
}

// Each sample index is four passes over the whole image (kernel/restir/restir_passes.h): each reads what the one
// before wrote at other pixels (the presampling the surfaces of a tile, the spatial reuse the neighbours' reservoirs).
template <bool kWithAovs>
FrameStats CpuBackend::renderRestirSamples(uint32_t samplesPerPixel) {
  const SceneView scene = flat_.hostView();
  const EmbreeTracer tracer(embree_.topLevel(), scene);
  const FilmView film = film_.view();
  const tbb::blocked_range2d<uint32_t> image(0, settings_.height, kTileSize, 0, settings_.width, kTileSize);
  tbb::combinable<FrameStats> stats;
  for (uint32_t i = 0; i < samplesPerPixel; ++i) {
    const uint32_t sample = nextSample_ + i;
    const RestirView restir = restir_.view(accumulated_ + i == 0);
    tbb::parallel_for(image, [&](const tbb::blocked_range2d<uint32_t>& tile) {
      FrameStats& local = stats.local();
      for (uint32_t y = tile.rows().begin(); y < tile.rows().end(); ++y)
        for (uint32_t x = tile.cols().begin(); x < tile.cols().end(); ++x)
          local.rays += restirPrimaryPass(scene, tracer, camera_, settings_, restir, x, y, sample);
    });
    tbb::parallel_for(tbb::blocked_range<uint32_t>(0, uint32_t(restirTileCount(settings_.width, settings_.height))),
                      [&](const tbb::blocked_range<uint32_t>& tiles) {
                        for (uint32_t t = tiles.begin(); t < tiles.end(); ++t)
                          restirPresamplePass(scene, settings_, restir, t, 0, kRestirPresampledLights, sample);
                      });
    tbb::parallel_for(image, [&](const tbb::blocked_range2d<uint32_t>& tile) {
      FrameStats& local = stats.local();
      for (uint32_t y = tile.rows().begin(); y < tile.rows().end(); ++y)
        for (uint32_t x = tile.cols().begin(); x < tile.cols().end(); ++x)
          local.rays += restirCandidatePass(scene, tracer, settings_, restir, x, y, sample);
    });
    tbb::parallel_for(image, [&](const tbb::blocked_range2d<uint32_t>& tile) {
      FrameStats& local = stats.local();
      for (uint32_t y = tile.rows().begin(); y < tile.rows().end(); ++y)
        for (uint32_t x = tile.cols().begin(); x < tile.cols().end(); ++x) {
          const PixelTally tally =
              accumulatePixel<kWithAovs>(film, size_t(y) * settings_.width + x, sample, 1, [&](uint32_t s) {
                return restirShadePass<kWithAovs>(scene, tracer, camera_, settings_, restir, x, y, s);
              });
          local.rays += tally.rays;
          local.invalidSamples += tally.invalidSamples;
        }
    });
    restir_.endSample(camera_);
  }
  return finishSamples(samplesPerPixel, stats);
}

AovImages CpuBackend::readAovs() const {
  if (!aovsEnabled_) throw std::logic_error("CpuBackend::readAovs without setAovsEnabled(true)");
  return film_.readAovs();
}

}  // namespace candela
