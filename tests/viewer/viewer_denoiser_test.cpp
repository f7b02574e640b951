// The viewer's denoiser choice on a real backend: each choice gives the image its filter gives, and the OptiX AI
// denoiser, where it cannot run, says why in one sentence.
#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>

#include "app/interactive/viewer_denoiser.h"
#include "backends/cpu/cpu_backend.h"
#include "image/filters/atrous.h"
#include "scene/builtin_scenes.h"

namespace candela {
namespace {

bool sameImage(const Image& a, const Image& b) {
  return a.width == b.width && a.height == b.height &&
         std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(Vec3)) == 0;
}

class ViewerDenoiserTest : public ::testing::Test {
 protected:
  void SetUp() override {
    Scene scene = makeCornellBox();
    const Camera camera = scene.camera.toCamera(40.0f / 32.0f);
    session.setScene(std::move(scene));
    session.setAovsEnabled(true);
    RenderSettings settings;
    settings.width = 40;
    settings.height = 32;
    settings.maxDepth = 3;
    session.renderFrame(camera, settings, 4, true);
  }

  RenderSession session{std::make_unique<CpuBackend>()};
  ViewerDenoiser denoiser;
};

TEST_F(ViewerDenoiserTest, EachChoiceGivesItsFiltersImage) {
  AtrousParams params;
  params.passes = 3;
  const Image plain = denoiser.apply(session, DenoiserChoice::None, params);
  EXPECT_TRUE(sameImage(plain, session.image()));
  const Image atrous = denoiser.apply(session, DenoiserChoice::Atrous, params);
  EXPECT_TRUE(sameImage(atrous, atrousDenoise(session.image(), session.backend().readAovs(), params)));
  EXPECT_FALSE(sameImage(atrous, plain)) << "the filter changed nothing";
}

// While the camera moves the a-trous choice runs the temporal filter; once the camera stands still long enough for
// the film to hold kTemporalSamples samples, the spatial filter again.
TEST_F(ViewerDenoiserTest, TheCameraMovingTurnsTheTemporalFilterOnUntilTheFilmHasConverged) {
  AtrousParams params;
  params.passes = 3;
  denoiser.apply(session, DenoiserChoice::Atrous, params);
  EXPECT_FALSE(denoiser.temporalActive());
  RenderSettings settings = session.appliedSettings();
  Scene scene = makeCornellBox();
  for (int frame = 1; frame <= 3; ++frame) {
    scene.camera.eye.x += 0.01f;
    session.renderFrame(scene.camera.toCamera(40.0f / 32.0f), settings, 1, true);
    const Image moving = denoiser.apply(session, DenoiserChoice::Atrous, params);
    EXPECT_TRUE(denoiser.temporalActive());
    // From the second moving frame on there is a history (the first is filtered as the spatial filter does at one
    // sample).
    if (frame > 1) {
      EXPECT_FALSE(sameImage(moving, atrousDenoise(session.image(), session.backend().readAovs(), params)));
    }
  }
  session.renderFrame(scene.camera.toCamera(40.0f / 32.0f), settings, ViewerDenoiser::kTemporalSamples, true);
  const Image still = denoiser.apply(session, DenoiserChoice::Atrous, params);
  EXPECT_FALSE(denoiser.temporalActive());
  EXPECT_TRUE(sameImage(still, atrousDenoise(session.image(), session.backend().readAovs(), params)));
}

TEST_F(ViewerDenoiserTest, TheOptixDenoiserIsUsedOnlyOncePrepared) {
  EXPECT_THROW(denoiser.apply(session, DenoiserChoice::Optix, {}), std::logic_error);
}

TEST_F(ViewerDenoiserTest, WithoutOptixInTheBuildItSaysSo) {
  if (inThisBuild(DenoiserChoice::Optix)) GTEST_SKIP() << "this build has the OptiX AI denoiser";
  try {
    denoiser.prepareOptix();
    FAIL() << "a build without OptiX prepared the OptiX AI denoiser";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(),
                 "the OptiX AI denoiser comes with the OptiX backend, which is not in this build (see "
                 "README, 'GPU backend')");
  }
}

TEST_F(ViewerDenoiserTest, TheOptixDenoiserRunsOrSaysWhyNotInOneSentence) {
  if (!inThisBuild(DenoiserChoice::Optix)) GTEST_SKIP() << "no OptiX in this build";
  try {
    denoiser.prepareOptix();
  } catch (const std::runtime_error& e) {
    const std::string why = e.what();
    EXPECT_EQ(why.find('\n'), std::string::npos) << why;
    GTEST_SKIP() << "the OptiX AI denoiser cannot run here: " << why;
  }
  const Image denoised = denoiser.apply(session, DenoiserChoice::Optix, {});
  EXPECT_EQ(denoised.width, 40u);
  EXPECT_EQ(denoised.height, 32u);
  for (Vec3 p : denoised.pixels) EXPECT_TRUE(isFinite(p));
  EXPECT_FALSE(sameImage(denoised, session.image()));
}

}  // namespace
}  // namespace candela
