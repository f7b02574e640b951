#include <gtest/gtest.h>

#include <cstring>
#include <stdexcept>
#include <string>

#include "app/denoising/film_denoiser.h"
#include "backends/cpu/cpu_backend.h"
#include "scene/builtin_scenes.h"

namespace candela {
namespace {

TEST(DenoiserChoice, NamesRoundTrip) {
  for (DenoiserChoice choice : kDenoiserChoices) EXPECT_EQ(parseDenoiser(denoiserName(choice)), choice);
}

TEST(DenoiserChoice, UnknownNameListsTheChoices) {
  try {
    parseDenoiser("magic");
    FAIL() << "parsed 'magic'";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "unknown denoiser 'magic' (use none, atrous, bilateral, temporal, optix)");
  }
}

TEST(DenoiserChoice, OnlyNoneReadsNoAovs) {
  for (DenoiserChoice choice : kDenoiserChoices) EXPECT_EQ(needsAovs(choice), choice != DenoiserChoice::None);
}

#if CANDELA_HAS_OPTIX
constexpr bool kOptixBackend = true;
#else
constexpr bool kOptixBackend = false;
#endif

TEST(DenoiserChoice, OptixOnlyWithTheOptixBackend) {
  EXPECT_EQ(inThisBuild(DenoiserChoice::Optix), kOptixBackend);
  EXPECT_EQ(notInThisBuild(DenoiserChoice::Optix).empty(), kOptixBackend);
  if (!kOptixBackend) {
    EXPECT_THROW(FilmDenoiser(DenoiserChoice::Optix, {}), std::runtime_error);
  }
}

// A small Cornell box on the CPU with the AOVs, for the film denoiser to read.
struct RenderedBox {
  Scene scene = makeCornellBox();
  CpuBackend backend;
  Camera camera;
  RenderedBox() {
    backend.setScene(scene);
    RenderSettings settings;
    settings.width = 32;
    settings.height = 24;
    backend.setSettings(settings);
    camera = scene.camera.toCamera(32.0f / 24.0f);
    backend.setCamera(camera);
    backend.setAovsEnabled(true);
    backend.render(4);
  }
};

// Each choice is the backend's film filter of that name: the film denoiser adds nothing of its own.
TEST(FilmDenoiser, AppliesTheBackendsFilmFilters) {
  RenderedBox box;
  const DenoiserParams params;
  const auto same = [](const Image& a, const Image& b) {
    return a.pixels.size() == b.pixels.size() &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(Vec3)) == 0;
  };
  EXPECT_TRUE(
      same(FilmDenoiser(DenoiserChoice::None, params).apply(box.backend, box.camera, false), box.backend.readImage()));
  EXPECT_TRUE(same(FilmDenoiser(DenoiserChoice::Atrous, params).apply(box.backend, box.camera, false),
                   box.backend.filters().atrous(params.atrous)));
  EXPECT_TRUE(same(FilmDenoiser(DenoiserChoice::Bilateral, params).apply(box.backend, box.camera, false),
                   box.backend.filters().bilateral(params.bilateral)));
  EXPECT_TRUE(same(FilmDenoiser(DenoiserChoice::Temporal, params).apply(box.backend, box.camera, false),
                   box.backend.filters().temporal(params.temporal)->denoise(box.camera, false)));
  EXPECT_FALSE(same(box.backend.filters().atrous(params.atrous), box.backend.readImage()));
}

}  // namespace
}  // namespace candela
