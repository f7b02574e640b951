#pragma once
#include <tbb/combinable.h>

#include <memory>

#include "backends/backend.h"
#include "backends/cpu/embree_scene.h"
#include "backends/cpu/host_film.h"
#include "backends/cpu/host_restir_buffers.h"
#include "backends/film_display.h"
#include "backends/film_filters.h"
#include "scene/flat_scene.h"

namespace candela {

// Embree traversal, TBB-parallel over image tiles.
class CpuBackend final : public Backend {
 public:
  CpuBackend();

  std::string name() const override { return "cpu"; }
  std::string deviceName() const override;

  void setScene(const Scene& scene) override;
  bool setMaterials(const std::vector<Material>& materials) override;
  void setEnvironment(const Environment& environment) override;
  void setInstanceTransforms(const Scene& scene) override;
  // Rebuilds the BVHs of the deformed meshes and the top-level BVH; the others stay.
  void setDeformedMeshes(const Scene& scene, const std::vector<uint32_t>& deformed) override;
  void setCamera(const Camera& camera) override;
  void setSettings(const RenderSettings& settings) override;

  FrameStats render(uint32_t samplesPerPixel) override;
  uint32_t accumulatedSamples() const override { return accumulated_; }
  void setNextSampleIndex(uint32_t index) override { nextSample_ = index; }
  FilmSums readFilm() const override { return film_.sums(); }
  void loadFilm(const FilmSums& film) override { film_.load(film); }
  Image readImage() const override { return film_.readImage(); }
  Image readEmission() const override { return film_.readEmission(); }
  void setAovsEnabled(bool enabled) override;
  bool aovsEnabled() const override { return aovsEnabled_; }
  AovImages readAovs() const override;
  const FilmFilters& filters() const override { return filters_; }
  // Reads the accumulated image straight from the film's sums.
  const FilmDisplay& display() const override { return display_; }

 private:
  // Restarts the film; ReSTIR's history survives only a camera move (setCamera), which its temporal reuse follows.
  void restart(bool keepRestirHistory = false);
  // kWithMedia: the scene has participating media, whose path (kernel/media/volume_path.h) scenes without them
  // do not run.
  template <bool kWithAovs, bool kWithMedia>
  FrameStats renderSamples(uint32_t samplesPerPixel);
  template <bool kWithAovs>
  FrameStats renderRestirSamples(uint32_t samplesPerPixel);
  FrameStats finishSamples(uint32_t samplesPerPixel, tbb::combinable<FrameStats>& stats);

  FlatScene flat_;
  EmbreeScene embree_;
  Camera camera_;
  RenderSettings settings_;
  bool aovsEnabled_ = false;
  HostFilm film_;
  HostRestirBuffers restir_;
  uint32_t accumulated_ = 0;
  uint32_t nextSample_ = 0;
  HostFilmFilters filters_{*this};
  HostFilmDisplay display_{*this, &film_.sums()};
};

}  // namespace candela
